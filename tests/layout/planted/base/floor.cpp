// Planted: a ground-floor module that reaches up into lib/.
#include "lib/api.h"
