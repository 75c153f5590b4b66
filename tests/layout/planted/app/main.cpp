// Another module: the public header is fine, the internal one is a finding.
#include "lib/api.h"

#include "lib/internal.h"
