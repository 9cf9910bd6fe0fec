#include "retroaa/version.h"

namespace retroaa {

const char* version() { return RETROAA_VERSION; }

}  // namespace retroaa
