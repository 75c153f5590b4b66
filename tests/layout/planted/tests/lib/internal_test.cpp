// Tests of lib/ may include its internals.
#include "lib/internal.h"
