# `cmake --install`: the urdfsnap binary, the stage libraries with their headers (under
# include/urdfsnap/<stage>/, included as "<stage>/<file>.h" as inside the project) and the CMake
# package urdfsnapConfig.cmake with urdfsnap_add_snapshot_test(). The modules (urdfsnap-meshes.so,
# urdfsnap-video.so, urdfsnap-serve.so) install themselves into lib/urdfsnap/ (cmake/urdfsnapModule.cmake), where
# the binary and programs linking urdfsnap_geometry or urdfsnap_video find them.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(urdfsnap_libraries urdfsnap_common urdfsnap_shard urdfsnap_xacro urdfsnap_model
  urdfsnap_geometry urdfsnap_image urdfsnap_texture urdfsnap_camera urdfsnap_scene urdfsnap_gl urdfsnap_render urdfsnap_request
  urdfsnap_snapshot urdfsnap_stream urdfsnap_bag urdfsnap_tf urdfsnap_display urdfsnap_motion urdfsnap_video)
set(urdfsnap_include_dir ${CMAKE_INSTALL_INCLUDEDIR}/urdfsnap)
set(urdfsnap_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/urdfsnap)

install(TARGETS urdfsnap ${urdfsnap_libraries} EXPORT urdfsnapTargets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${urdfsnap_include_dir})
# Only the public API's headers: never a stage's internal/ folder (private headers by place), nor
# the commands' own libraries (cli, animation, docs, serve: not installed).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${urdfsnap_include_dir}
  FILES_MATCHING PATTERN "*.h"
  PATTERN "cli" EXCLUDE
  PATTERN "animation" EXCLUDE
  PATTERN "docs" EXCLUDE
  PATTERN "serve" EXCLUDE
  PATTERN "internal" EXCLUDE)
install(EXPORT urdfsnapTargets NAMESPACE urdfsnap:: DESTINATION ${urdfsnap_package_dir})

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/urdfsnapConfig.cmake.in
  ${PROJECT_BINARY_DIR}/urdfsnapConfig.cmake INSTALL_DESTINATION ${urdfsnap_package_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/urdfsnapConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES
  ${PROJECT_BINARY_DIR}/urdfsnapConfig.cmake
  ${PROJECT_BINARY_DIR}/urdfsnapConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/urdfsnapSnapshotTest.cmake
  DESTINATION ${urdfsnap_package_dir})
