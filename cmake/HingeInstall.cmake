# install() and export so that find_package(hinge) gives hinge::reference (and hinge::fast).
include(CMakePackageConfigHelpers)
install(TARGETS hinge_reference hinge_reference_types hinge_io hinge_fast hinge_baselines hinge_methods hinge_warnings EXPORT hingeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY reference/include/ io/include/ fast/include/ baselines/include/ methods/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT hingeTargets NAMESPACE hinge:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hinge)
configure_package_config_file(cmake/hingeConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/hingeConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hinge)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/hingeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hingeConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/hingeConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hinge)
