# Turns each shader file into a C++ string constant at build time so the
# library needs no files at run time. The .glsl files stay the source of truth.
function(curvetext_embed_shaders out_cpp)
  set(inputs ${ARGN})
  set(script "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/EmbedShadersScript.cmake")
  add_custom_command(
    OUTPUT "${out_cpp}"
    COMMAND ${CMAKE_COMMAND} -DOUT=${out_cpp} "-DINPUTS=${inputs}" -P "${script}"
    DEPENDS ${inputs} "${script}"
    COMMENT "Embedding shaders"
    VERBATIM)
endfunction()
