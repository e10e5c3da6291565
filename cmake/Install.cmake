# Install rules and the CMake package of the library: the library, its public headers
# (core/include/exactccd only), the generated version header, the `exactccd` command (and the
# study program it runs) when built, exactccdConfig.cmake + exactccdConfigVersion.cmake
# (SameMajorVersion) with the exported target exactccd::exactccd, and the pkg-config file
# exactccd.pc. Included from the top level.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(EXACTCCD_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/exactccd"
    CACHE STRING "Where exactccdConfig.cmake is installed, relative to the prefix")

install(TARGETS exactccd EXPORT exactccdTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/exactccd
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/include/exactccd/version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/exactccd)
if(TARGET exactccd_cli)
  install(TARGETS exactccd_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
if(TARGET exactccd_study)  # beside the command, which runs it for `exactccd study`
  install(TARGETS exactccd_study RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(EXPORT exactccdTargets NAMESPACE exactccd:: DESTINATION ${EXACTCCD_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/exactccdConfig.cmake.in
  ${PROJECT_BINARY_DIR}/exactccdConfig.cmake INSTALL_DESTINATION ${EXACTCCD_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/exactccdConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/exactccdConfig.cmake
              ${PROJECT_BINARY_DIR}/exactccdConfigVersion.cmake
        DESTINATION ${EXACTCCD_INSTALL_CMAKEDIR})

# pkg-config: relocatable, the prefix found from the file's own place (${pcfiledir}), so that
# `cmake --install --prefix <any>` gives a working file.
file(RELATIVE_PATH EXACTCCD_PC_TO_PREFIX "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
configure_file(${PROJECT_SOURCE_DIR}/cmake/exactccd.pc.in ${PROJECT_BINARY_DIR}/exactccd.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/exactccd.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
