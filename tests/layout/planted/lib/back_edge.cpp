// lib/ reaching back into app/: closes the cycle lib -> app -> lib (a finding).
#include "app/app.h"
