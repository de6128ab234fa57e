# `cmake --install`: the graspecmf command, the bundled model, the Python module, the public
# headers and the layer libraries with a CMake package (find_package(graspecmf)) that exports
# graspecmf::graspecmf (every layer), graspecmf::torch_free (every layer that needs no LibTorch)
# and each layer as graspecmf::<layer>. docs/install.md.
include(CMakePackageConfigHelpers)

get_property(layers GLOBAL PROPERTY GRASPECMF_LAYERS)
set(torch_free_layers core lie geometry metrics viz gripper data sim dataset formats camera)

add_library(graspecmf_torch_free INTERFACE)
add_library(graspecmf_all INTERFACE)
foreach(layer ${torch_free_layers})
  target_link_libraries(graspecmf_torch_free INTERFACE graspecmf_${layer})
endforeach()
target_link_libraries(graspecmf_all INTERFACE ${layers})
set_target_properties(graspecmf_torch_free PROPERTIES EXPORT_NAME torch_free)
set_target_properties(graspecmf_all PROPERTIES EXPORT_NAME graspecmf)

install(TARGETS ${layers} graspecmf_torch_free graspecmf_all EXPORT graspecmfTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/graspecmf DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/graspecmf)
install(EXPORT graspecmfTargets NAMESPACE graspecmf:: DESTINATION ${config_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/graspecmfConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/graspecmfConfig.cmake
                              INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/graspecmfConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/graspecmfConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/graspecmfConfigVersion.cmake DESTINATION ${config_dir})

install(TARGETS graspecmf RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/models/mugs
        DESTINATION ${CMAKE_INSTALL_DATADIR}/graspecmf/models)
# The Python module installs from python/CMakeLists.txt.
