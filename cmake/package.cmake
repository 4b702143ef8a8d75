# Install and package: `cmake --install build --prefix P` installs the public headers
# (P/include/rmsc/), one static library holding the API and the engine layers it uses
# (P/lib/librmsc.a), a CMake package (P/lib/cmake/rmsc/: find_package(rmsc CONFIG) ->
# rmsc::rmsc, with a version file) and a pkg-config file (P/lib/pkgconfig/rmsc.pc). Nothing
# else is installed. The compatibility rule is in docs/embedding.md ("What is stable").
include(CMakePackageConfigHelpers)

# The layers the API needs, and the GL loader, as one archive (GNU ar's MRI script).
set(rmsc_library_layers rmsc_api rmsc_render rmsc_gl rmsc_prepare rmsc_scene rmsc_sdf rmsc_core
                        rmsc_glad)
set(rmsc_archive ${CMAKE_BINARY_DIR}/lib/librmsc.a)
set(rmsc_mri "CREATE ${rmsc_archive}\n")
foreach(layer ${rmsc_library_layers})
  string(APPEND rmsc_mri "ADDLIB $<TARGET_FILE:${layer}>\n")
endforeach()
string(APPEND rmsc_mri "SAVE\nEND\n")
file(GENERATE OUTPUT ${CMAKE_BINARY_DIR}/librmsc.mri CONTENT "${rmsc_mri}")
add_custom_command(
  OUTPUT ${rmsc_archive}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/lib
  COMMAND ${CMAKE_COMMAND} -E rm -f ${rmsc_archive}
  COMMAND sh -c "${CMAKE_AR} -M < ${CMAKE_BINARY_DIR}/librmsc.mri"
  DEPENDS ${rmsc_library_layers} ${CMAKE_BINARY_DIR}/librmsc.mri
  COMMENT "Archiving librmsc.a"
  VERBATIM)
add_custom_target(rmsc_library ALL DEPENDS ${rmsc_archive})

install(FILES ${rmsc_archive} DESTINATION lib)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/engine/api/include/rmsc DESTINATION include
        FILES_MATCHING PATTERN "*.hpp")
install(FILES ${CMAKE_BINARY_DIR}/engine/api_include/rmsc/version.hpp DESTINATION include/rmsc)

configure_file(${PROJECT_SOURCE_DIR}/cmake/rmscConfig.cmake.in
               ${CMAKE_BINARY_DIR}/package/rmscConfig.cmake @ONLY)
# While the major version is 0 a minor release may change the API: only the same major.minor
# is compatible (docs/embedding.md).
write_basic_package_version_file(${CMAKE_BINARY_DIR}/package/rmscConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/package/rmscConfig.cmake
              ${CMAKE_BINARY_DIR}/package/rmscConfigVersion.cmake DESTINATION lib/cmake/rmsc)
configure_file(${PROJECT_SOURCE_DIR}/cmake/rmsc.pc.in ${CMAKE_BINARY_DIR}/package/rmsc.pc @ONLY)
install(FILES ${CMAKE_BINARY_DIR}/package/rmsc.pc DESTINATION lib/pkgconfig)
