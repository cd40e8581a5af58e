# Installs the exported targets and a package config so that find_package(voronav) works.
include(CMakePackageConfigHelpers)
install(EXPORT voronavTargets NAMESPACE voronav:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/voronav)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/voronavConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/voronavConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/voronav)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/voronavConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/voronavConfig.cmake
              ${PROJECT_BINARY_DIR}/voronavConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/voronav)
