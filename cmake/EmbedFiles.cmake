# Embeds text files (GLSL shaders, the live view's page) into C++ at build time, so the binary
# looks up no file at run time.
#
# urdfsnap_embed_files(OUT_CPP HEADER h NAMESPACE ns FUNCTION fn FILES file...) adds a custom
# command producing OUT_CPP, which defines `std::string_view ns::fn(std::string_view name)`
# (declared in HEADER) over the files' contents, keyed by file name ("lit.vert"); an unknown name
# throws urdfsnap::Error.
function(urdfsnap_embed_files out_cpp)
  cmake_parse_arguments(ARG "" "HEADER;NAMESPACE;FUNCTION" "FILES" ${ARGN})
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} "-DINPUTS=${ARG_FILES}" -DHEADER=${ARG_HEADER}
            -DNAMESPACE=${ARG_NAMESPACE} -DFUNCTION=${ARG_FUNCTION}
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake
    DEPENDS ${ARG_FILES} ${PROJECT_SOURCE_DIR}/cmake/EmbedFilesScript.cmake
    COMMENT "Embedding ${ARG_FUNCTION} files"
    VERBATIM)
endfunction()
