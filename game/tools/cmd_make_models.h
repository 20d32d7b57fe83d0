// `oceanbox make-models`: writes the project's own glTF models (assets/models/*.gltf).
#pragma once
#include <string>

namespace ob::game {

struct ShapeModel;

/// The model as a self-contained glTF 2.0 file: pretty JSON, one embedded base64 buffer,
/// one mesh with a primitive and a material per part. The same bytes on every run.
std::string gltfText(const ShapeModel& model);

/// Writes ship.gltf, fish.gltf, cannonball.gltf and cannon.gltf into `outDir` (created if
/// missing). Returns ob::EXIT_OK; throws ob::InputError if the folder cannot be made or
/// written.
int makeModels(const std::string& outDir);

} // namespace ob::game
