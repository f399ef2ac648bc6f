# SPDX-License-Identifier: BSD-3-Clause
# Install rules: the public headers, the shared and static libraries, the
# projcurve command (once src/cli defines it), a pkg-config file and a CMake
# package, so that
#   cmake --install build --prefix P
# gives a tree usable through `pkg-config projcurve` and
# `find_package(projcurve CONFIG)` -> projcurve::projcurve (shared) and
# projcurve::projcurve_static. Both files are relocatable: they find the
# prefix from their own location, so --prefix at install time just works.
include(CMakePackageConfigHelpers)

set(PROJCURVE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/projcurve)

# projcurve.hpp: the header-only C++17 wrappers, beside the C header.
install(FILES ${PROJECT_SOURCE_DIR}/include/projcurve.h
              ${PROJECT_SOURCE_DIR}/include/projcurve.hpp
              ${PROJECT_BINARY_DIR}/include/projcurve_version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

install(TARGETS projcurve projcurve_static EXPORT projcurveTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})

# The licence beside the documentation, as distributions expect it.
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The command-line tool (target projcurve_cli of src/cli, file `projcurve`).
if(TARGET projcurve_cli)
  install(TARGETS projcurve_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(EXPORT projcurveTargets NAMESPACE projcurve::
        FILE projcurveTargets.cmake DESTINATION ${PROJCURVE_CMAKE_DIR})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/projcurveConfig.cmake.in
  ${PROJECT_BINARY_DIR}/projcurveConfig.cmake
  INSTALL_DESTINATION ${PROJCURVE_CMAKE_DIR})
# Same major version = same ABI (the SONAME carries the major version).
write_basic_package_version_file(${PROJECT_BINARY_DIR}/projcurveConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMajorVersion)
install(FILES ${PROJECT_BINARY_DIR}/projcurveConfig.cmake
              ${PROJECT_BINARY_DIR}/projcurveConfigVersion.cmake
        DESTINATION ${PROJCURVE_CMAKE_DIR})

# pkg-config: ${pcfiledir} is <libdir>/pkgconfig, so the prefix is the
# relative path from there back up (works for lib and lib/<multiarch>).
if(IS_ABSOLUTE ${CMAKE_INSTALL_LIBDIR} OR IS_ABSOLUTE ${CMAKE_INSTALL_INCLUDEDIR})
  set(PROJCURVE_PC_PREFIX ${CMAKE_INSTALL_PREFIX})
else()
  file(RELATIVE_PATH PROJCURVE_PC_UP /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
  string(REGEX REPLACE "/$" "" PROJCURVE_PC_UP "${PROJCURVE_PC_UP}")
  set(PROJCURVE_PC_PREFIX "\${pcfiledir}/${PROJCURVE_PC_UP}")
endif()
cmake_path(APPEND PROJCURVE_PC_LIBDIR "\${prefix}" ${CMAKE_INSTALL_LIBDIR})
cmake_path(APPEND PROJCURVE_PC_INCLUDEDIR "\${prefix}" ${CMAKE_INSTALL_INCLUDEDIR})
if(IS_ABSOLUTE ${CMAKE_INSTALL_LIBDIR})
  set(PROJCURVE_PC_LIBDIR ${CMAKE_INSTALL_LIBDIR})
endif()
if(IS_ABSOLUTE ${CMAKE_INSTALL_INCLUDEDIR})
  set(PROJCURVE_PC_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR})
endif()
configure_file(${PROJECT_SOURCE_DIR}/pkgconfig/projcurve.pc.in
               ${PROJECT_BINARY_DIR}/projcurve.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/projcurve.pc
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
