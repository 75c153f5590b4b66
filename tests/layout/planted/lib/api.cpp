// The module itself may include its internals.
#include "lib/api.h"
#include "lib/internal.h"

int api() { return helper(); }
