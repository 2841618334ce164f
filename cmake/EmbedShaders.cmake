# Embeds GLSL files into C++ at build time, so the binary looks up no file at run time.
#
# urdfsnap_embed_shaders(OUT_CPP file1.glsl ...) adds a custom command producing OUT_CPP, which
# defines urdfsnap::render::EmbeddedShader(name) (declared in render/embedded_shaders.h) over the
# files' contents, keyed by file name ("lit.vert").
function(urdfsnap_embed_shaders out_cpp)
  set(inputs ${ARGN})
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} "-DINPUTS=${inputs}"
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    DEPENDS ${inputs} ${PROJECT_SOURCE_DIR}/cmake/EmbedShadersScript.cmake
    COMMENT "Embedding shaders"
    VERBATIM)
endfunction()
