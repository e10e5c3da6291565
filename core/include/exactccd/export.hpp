// EXACTCCD_API marks what the library exports. The library is compiled with hidden visibility
// (-fvisibility=hidden), so a shared build exports the public API only; internal symbols (exact/,
// filters/, CGAL, GMP helpers) stay private to it.
#pragma once

#if defined(_WIN32) && !defined(EXACTCCD_STATIC)
#  if defined(EXACTCCD_BUILDING)
#    define EXACTCCD_API __declspec(dllexport)
#  else
#    define EXACTCCD_API __declspec(dllimport)
#  endif
#elif defined(__GNUC__) || defined(__clang__)
#  define EXACTCCD_API __attribute__((visibility("default")))
#else
#  define EXACTCCD_API
#endif
