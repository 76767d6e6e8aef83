include(CMakePackageConfigHelpers)

install(TARGETS edgeland_kernel edgeland_clip edgeland_spatial edgeland_io edgeland_game
  edgeland_engine edgeland
  EXPORT edgelandTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY kernel/include/ clip/include/ spatial/include/ io/include/ game/include/
  adapters/engine/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The C API (capi/): the shared library (with its SONAME links) and the static one, and edgeland.h.
if(TARGET edgeland_c_shared)
  install(TARGETS edgeland_c_shared edgeland_c_static EXPORT edgelandTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(DIRECTORY capi/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endif()
install(EXPORT edgelandTargets NAMESPACE edgeland:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/edgeland)
# The Box2D adapter, when built, in an export set of its own: edgelandConfig.cmake loads it only
# where Box2D is found, so a user without Box2D still finds the rest.
if(TARGET edgeland_box2d)
  install(TARGETS edgeland_box2d EXPORT edgelandBox2dTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY adapters/box2d/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT edgelandBox2dTargets NAMESPACE edgeland::
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/edgeland)
endif()
configure_package_config_file(cmake/edgelandConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/edgelandConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/edgeland)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/edgelandConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/edgelandConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/edgelandConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/edgeland)
