#pragma once
// The planted module's interface.
int api();
