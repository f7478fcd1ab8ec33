// The fuzz targets that build meshes, each under a name of its own so that
// mesh_hash_test can run all of them on their corpora in one program.
#define LLVMFuzzerTestOneInput mesh_hash_outline_input
#include "outline_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput

#define LLVMFuzzerTestOneInput mesh_hash_svg_path_input
#include "svg_path_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput

#define LLVMFuzzerTestOneInput mesh_hash_nurbs_json_input
#include "nurbs_json_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput

#define LLVMFuzzerTestOneInput mesh_hash_svg_input
#include "svg_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput

#define LLVMFuzzerTestOneInput mesh_hash_font_input
#include "font_fuzzer.cpp"
#undef LLVMFuzzerTestOneInput
