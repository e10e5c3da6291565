# Builds ipc-toolkit without network access: include() this file, then add ipc-toolkit's source
# folder with add_subdirectory. It
#   - creates the targets ipc-toolkit's recipes ask for (Eigen3::Eigen, TBB::tbb,
#     spdlog::spdlog, nlohmann_json::nlohmann_json, TinyAD::TinyAD, Catch2::Catch2) from
#     Debian's packages and local source folders, so that those recipes return early;
#   - points CPM at local source folders for libigl, Tight-Inclusion, scalable-ccd and
#     finite-diff, and FetchContent at libigl-predicates;
#   - turns off the optional dependencies (SIMD/xsimd, robin-map, abseil, filib, CUDA), the
#     tests and the Python module;
#   - provides ipc_toolkit_offline_trim(): call it after add_subdirectory to compile only the
#     library sources the CCD tests need.
#
# Input: IPC_OFFLINE_SOURCES, a folder holding the exported sources (see ../README.md):
#   libigl/ (v2.6.0)  tight-inclusion/ (v1.0.6)  scalable-ccd/ (c80af01c)  finite-diff/ (v1.0.4)
#   predicates/ (libigl-predicates decb7bc)  catch2/ (v3.7.1)  tinyad/ (upstream)
# and CPM_SOURCE_CACHE, a folder whose cpm/ holds CPM_0.38.1.cmake, CPM_0.40.2.cmake and
# CPM_0.42.0.cmake (the CPM.cmake versions the projects' recipes name).
# Debian packages: libeigen3-dev libtbb-dev libspdlog-dev libfmt-dev nlohmann-json3-dev.

set(IPC_OFFLINE_SOURCES "" CACHE PATH "Folder of the exported dependency sources")
if(NOT IS_DIRECTORY "${IPC_OFFLINE_SOURCES}/libigl")
  message(FATAL_ERROR "IPC_OFFLINE_SOURCES (${IPC_OFFLINE_SOURCES}) has no libigl/ folder")
endif()
if(NOT CPM_SOURCE_CACHE OR NOT EXISTS "${CPM_SOURCE_CACHE}/cpm/CPM_0.42.0.cmake")
  message(FATAL_ERROR "CPM_SOURCE_CACHE must hold cpm/CPM_0.42.0.cmake (and 0.38.1, 0.40.2)")
endif()
set(_ipc_offline_dir "${CMAKE_CURRENT_LIST_DIR}")

# Options of ipc-toolkit and its dependencies.
set(IPC_TOOLKIT_BUILD_TESTS OFF CACHE BOOL "" FORCE)
set(IPC_TOOLKIT_BUILD_PYTHON OFF CACHE BOOL "" FORCE)
set(IPC_TOOLKIT_WITH_CUDA OFF CACHE BOOL "" FORCE)
set(IPC_TOOLKIT_WITH_SIMD OFF CACHE BOOL "" FORCE)
set(IPC_TOOLKIT_WITH_ROBIN_MAP OFF CACHE BOOL "" FORCE)
set(IPC_TOOLKIT_WITH_ABSEIL OFF CACHE BOOL "" FORCE)
set(IPC_TOOLKIT_WITH_FILIB OFF CACHE BOOL "" FORCE)
set(IPC_TOOLKIT_WITH_CCACHE OFF CACHE BOOL "" FORCE)
set(CPM_USE_LOCAL_PACKAGES OFF CACHE BOOL "" FORCE)
set(CPM_DOWNLOAD_ALL OFF CACHE BOOL "" FORCE)
set(CPM_libigl_SOURCE "${IPC_OFFLINE_SOURCES}/libigl" CACHE PATH "" FORCE)
set(CPM_Tight-Inclusion_SOURCE "${IPC_OFFLINE_SOURCES}/tight-inclusion" CACHE PATH "" FORCE)
set(CPM_scalable-ccd_SOURCE "${IPC_OFFLINE_SOURCES}/scalable-ccd" CACHE PATH "" FORCE)
set(CPM_finite-diff_SOURCE "${IPC_OFFLINE_SOURCES}/finite-diff" CACHE PATH "" FORCE)
set(FETCHCONTENT_SOURCE_DIR_PREDICATES "${IPC_OFFLINE_SOURCES}/predicates" CACHE PATH "" FORCE)
set(FETCHCONTENT_FULLY_DISCONNECTED ON CACHE BOOL "" FORCE)

# Eigen, TBB, nlohmann_json: Debian's packages and their CMake packages.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3 REQUIRED)

# spdlog: Debian's package uses the external fmt; ipc-toolkit and Tight-Inclusion include
# <spdlog/fmt/bundled/*.h>, which the shims map to <fmt/*.h>.
find_package(spdlog REQUIRED)
if(NOT TARGET ipc_offline_spdlog_shim)
  add_library(ipc_offline_spdlog_shim INTERFACE)
  target_include_directories(ipc_offline_spdlog_shim INTERFACE "${_ipc_offline_dir}/shims/spdlog-fmt")
  target_link_libraries(ipc_offline_spdlog_shim INTERFACE fmt::fmt)
  set_property(TARGET spdlog::spdlog APPEND PROPERTY INTERFACE_LINK_LIBRARIES
               ipc_offline_spdlog_shim)
endif()

# TinyAD: upstream headers plus an empty TinyAD::ScalarBase (shims/tinyad/TinyAD/Scalar.hh).
if(NOT TARGET TinyAD::TinyAD)
  add_library(ipc_offline_tinyad INTERFACE)
  target_include_directories(ipc_offline_tinyad INTERFACE "${_ipc_offline_dir}/shims/tinyad"
                                                          "${IPC_OFFLINE_SOURCES}/tinyad/include")
  target_link_libraries(ipc_offline_tinyad INTERFACE Eigen3::Eigen TBB::tbb)
  add_library(TinyAD::TinyAD ALIAS ipc_offline_tinyad)
endif()

# Catch2: the amalgamated single file, and forwarding headers for <catch2/...> includes.
if(NOT TARGET Catch2::Catch2 AND EXISTS "${IPC_OFFLINE_SOURCES}/catch2/extras/catch_amalgamated.cpp")
  set(_catch_shims "${CMAKE_BINARY_DIR}/ipc_offline_catch2_shims")
  foreach(h catch_test_macros.hpp catch_approx.hpp catch_session.hpp catch_template_test_macros.hpp
            benchmark/catch_benchmark.hpp generators/catch_generators.hpp
            generators/catch_generators_adapters.hpp generators/catch_generators_random.hpp
            generators/catch_generators_range.hpp matchers/catch_matchers.hpp
            matchers/catch_matchers_floating_point.hpp)
    file(CONFIGURE OUTPUT "${_catch_shims}/catch2/${h}"
         CONTENT "#pragma once\n#include <catch_amalgamated.hpp>\n")
  endforeach()
  add_library(ipc_offline_catch2 STATIC
              "${IPC_OFFLINE_SOURCES}/catch2/extras/catch_amalgamated.cpp")
  target_include_directories(ipc_offline_catch2 PUBLIC "${_catch_shims}"
                                                       "${IPC_OFFLINE_SOURCES}/catch2/extras")
  target_compile_features(ipc_offline_catch2 PUBLIC cxx_std_17)
  # ipc-toolkit's tests bring their own main() (main.cpp).
  target_compile_definitions(ipc_offline_catch2 PRIVATE CATCH_AMALGAMATED_CUSTOM_MAIN)
  add_library(Catch2::Catch2 ALIAS ipc_offline_catch2)
endif()

# Compile only what the CCD tests need: ipc-toolkit's SOURCES without these folders.
function(ipc_toolkit_offline_trim)
  get_target_property(_srcs ipc_toolkit SOURCES)
  list(FILTER _srcs EXCLUDE REGEX
       "/(smooth_contact|ogc|adhesion|friction|potentials|collisions/tangential)/")
  set_property(TARGET ipc_toolkit PROPERTY SOURCES ${_srcs})
endfunction()
