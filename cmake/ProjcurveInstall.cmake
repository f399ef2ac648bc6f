# Install rules (headers, libraries, pkg-config, CMake package): see docs/.
install(FILES include/projcurve.h ${PROJECT_BINARY_DIR}/include/projcurve_version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS projcurve projcurve_static EXPORT projcurveTargets
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
