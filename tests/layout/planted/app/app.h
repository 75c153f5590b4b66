#pragma once
// The planted app's interface.
int app();
