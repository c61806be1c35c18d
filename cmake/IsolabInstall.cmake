# cmake --install: the isolab executable, the plot scripts it runs (share/isolab/scripts, which
# --plot finds relative to the executable), the public headers, the libraries and a CMake package
# (find_package(isolab); targets isolab::<area>). tests/install/ builds a consumer against it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(isolab_libraries core hysteresis structure integrators spectra identification diagnosis io
                     model analysis cyclic building design study)
# KLU's and HDF5's include paths and libraries travel with io.
set(isolab_library_targets isolab_klu isolab_hdf5)
foreach(area ${isolab_libraries})
  set_target_properties(isolab_${area} PROPERTIES EXPORT_NAME ${area})
  isolab_pass_sanitizers_on(isolab_${area})
  list(APPEND isolab_library_targets isolab_${area})
endforeach()
set_target_properties(isolab_klu PROPERTIES EXPORT_NAME klu)
set_target_properties(isolab_hdf5 PROPERTIES EXPORT_NAME hdf5)

install(TARGETS isolab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The front (bin/isolab) starts them for its other commands (src/cli/heavy_commands.h).
install(TARGETS isolab_search isolab_studies RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/isolab)
install(TARGETS ${isolab_library_targets} EXPORT isolabTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/isolab DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
file(GLOB isolab_installed_scripts ${PROJECT_SOURCE_DIR}/scripts/plot_*.py
     ${PROJECT_SOURCE_DIR}/scripts/design_html.py)
install(PROGRAMS ${isolab_installed_scripts} DESTINATION ${CMAKE_INSTALL_DATADIR}/isolab/scripts)

install(EXPORT isolabTargets NAMESPACE isolab::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/isolab)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/isolabConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/isolabConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/isolab)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/isolabConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/isolabConfig.cmake
              ${PROJECT_BINARY_DIR}/isolabConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/isolab)
