// The library's own version, for programs that check the one they run against.
#include "exactccd/version.hpp"

namespace exactccd {

const char* library_version() noexcept { return EXACTCCD_VERSION_STRING; }

}  // namespace exactccd
