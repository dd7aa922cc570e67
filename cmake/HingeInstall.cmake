# install() and export: find_package(hinge) gives hinge::reference, hinge::fast, hinge::oracle (and the
# libraries they use: hinge::io, hinge::methods, hinge::baselines, hinge::core); pkg-config
# gives hinge (docs/packaging.md). The package finds its dependencies where it is used (find_dependency,
# cmake/FindHingeSystemLibraries.cmake), is relocatable (paths relative to the installed config) and
# passes no compile option of the project's own (warnings, -ffp-contract) to consumers.
include(CMakePackageConfigHelpers)
install(TARGETS hinge_core hinge_reference hinge_io hinge_fast hinge_baselines hinge_methods hinge_conformance EXPORT hingeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY core/include/ reference/include/ io/include/ conformance/include/ fast/include/ baselines/include/ methods/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT hingeTargets NAMESPACE hinge:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hinge)
configure_package_config_file(cmake/hingeConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/hingeConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hinge)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/hingeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hingeConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/hingeConfigVersion.cmake
              cmake/FindHingeSystemLibraries.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/hinge)

# pkg-config: one package, hinge, with every library (static: the linker keeps what is used). MPFI and
# libquadmath ship no .pc file, so they are named by -l; the others are in Requires.
# The prefix is found relative to the .pc file, so the installed tree can move.
file(RELATIVE_PATH HINGE_PC_TO_PREFIX /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
if(TARGET Quadmath::quadmath)
  set(HINGE_PC_QUADMATH "-lquadmath ")
else()
  set(HINGE_PC_QUADMATH "")
endif()
configure_file(cmake/hinge.pc.in ${CMAKE_CURRENT_BINARY_DIR}/hinge.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/hinge.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
