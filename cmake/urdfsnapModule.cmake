# urdfsnap's modules (src/common/module_loader.h): parts built as shared objects that the commands
# needing them open with dlopen, so that the others never load their libraries. A module is built
# beside the urdfsnap binary (where the build tree's programs find it) and installed into
# lib/urdfsnap/; the Debian package installs under URDFSNAP_PACKAGE_PREFIX.
include(GNUInstallDirs)
set(URDFSNAP_MODULE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/urdfsnap)
set(URDFSNAP_PACKAGE_PREFIX /usr)

# urdfsnap_add_module(TARGET FILE_NAME source...): the module FILE_NAME ("urdfsnap-video.so").
# It carries its own copies of the urdfsnap libraries it links, all hidden: it exports only its
# entry point (marked visible in its source), so that nothing in it can
# stand in for the loading program's own code or the other way round.
function(urdfsnap_add_module target file_name)
  add_library(${target} MODULE ${ARGN})
  get_filename_component(stem ${file_name} NAME_WE)
  set_target_properties(${target} PROPERTIES
    PREFIX "" OUTPUT_NAME ${stem} SUFFIX ".so"
    LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}
    CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON)
  target_link_options(${target} PRIVATE -Wl,--exclude-libs,ALL)
  if(NOT URDFSNAP_SANITIZE)
    # every symbol resolved at link time (the sanitizers' runtime is the program's, so not there)
    target_link_options(${target} PRIVATE -Wl,-z,defs)
  endif()
  install(TARGETS ${target} LIBRARY DESTINATION ${URDFSNAP_MODULE_INSTALL_DIR})
endfunction()
