// The one translation unit that compiles tinygltf's implementation (Debian ships the header;
// the define must appear exactly once in the program).
#define TINYGLTF_IMPLEMENTATION
#include "assets/gltf_library.h"
