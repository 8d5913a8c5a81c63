// The tinygltf implementation (header-only library; compiled here exactly once).
#define TINYGLTF_IMPLEMENTATION
#include "io/tinygltf_config.hpp"
