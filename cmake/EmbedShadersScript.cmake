# Called by curvetext_embed_shaders: writes OUT with one
#   extern const char* const kShader_<name>;
# definition per input file, using a raw string literal.
set(content "// Generated from shaders/*.glsl by cmake/EmbedShadersScript.cmake. Do not edit.\n")
string(APPEND content "#include \"gpu/shader_sources.hpp\"\n\nnamespace curvetext::shader_source {\n")
foreach(input IN LISTS INPUTS)
  get_filename_component(name "${input}" NAME)
  string(REPLACE "." "_" ident "${name}")
  file(READ "${input}" text)
  string(APPEND content "extern const char* const ${ident};\nconst char* const ${ident} = R\"CTSHADER(${text})CTSHADER\";\n")
endforeach()
string(APPEND content "}  // namespace curvetext::shader_source\n")
file(WRITE "${OUT}.tmp" "${content}")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
