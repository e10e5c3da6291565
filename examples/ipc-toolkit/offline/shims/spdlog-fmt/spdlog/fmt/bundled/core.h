// Debian's spdlog uses the external fmt: map spdlog's bundled-fmt header to it.
#pragma once
#include <fmt/core.h>
