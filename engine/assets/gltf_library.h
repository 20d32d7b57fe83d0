// tinygltf as oceanbox builds it: meshes and materials only, no image codecs (textures are
// not read), the same configuration in every file that includes it.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
