#pragma once
// A public header that lets the internal one out (a finding).
#include "lib/internal.h"
