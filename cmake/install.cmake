# `cmake --install`: every canopy library as canopy::NAME (canopy::sim, canopy::render, …),
# their headers under include/canopy/, and a CMake package (canopyConfig.cmake) that finds the
# same third-party packages the build used. examples/consumer shows a project using it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(canopy_libraries GLOBAL PROPERTY CANOPY_LIBRARIES)
# Building the program builds every installed library, so that `cmake --install` works right
# after the README's first command (tests/app/install_after_first_command_test.py).
add_dependencies(canopy ${canopy_libraries})
# canopy_warnings carries only our warning flags; it is linked privately but a static library's
# private links still appear in the export.
set_target_properties(canopy_warnings PROPERTIES EXPORT_NAME warnings)
install(TARGETS ${canopy_libraries} canopy_warnings EXPORT canopyTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(dir core world sensing agents spec metrics sim experiments render analysis replay)
  if(EXISTS ${PROJECT_SOURCE_DIR}/${dir})
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/canopy/${dir}
            FILES_MATCHING PATTERN "*.h")
  endif()
endforeach()
install(EXPORT canopyTargets NAMESPACE canopy::
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/canopy)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/canopyConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/canopyConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/canopy)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/canopyConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/canopyConfig.cmake ${PROJECT_BINARY_DIR}/canopyConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/canopy)
