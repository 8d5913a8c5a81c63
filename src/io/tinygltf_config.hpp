// The one place that configures tinygltf for ramus: geometry only (no image decoding or
// writing, no external images), JSON through the system's nlohmann/json. Include this instead
// of <tiny_gltf.h> so every translation unit sees the same declarations.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_USE_CPP14

#include <tiny_gltf.h>
