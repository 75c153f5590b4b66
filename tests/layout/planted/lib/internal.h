#pragma once
// Internal to lib/: only lib/ and tests/lib/ may include it.
int helper();
