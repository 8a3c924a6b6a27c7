// Exporting a grown grass field for other runtimes and tools (issue 8): one glTF 2.0 file per
// layer (blades as EXT_mesh_gpu_instancing instances of a unit blade mesh, the terrain, the
// painted maps as PNG), every layer in one .glb with one terrain (issue 25), or the raw GPU buffers (the 64-byte blades of SPEC §1, the patch table,
// the maps as float32) with a manifest.json describing them. Units are metres, +Y is up in a
// right-handed frame, angles are radians. Layout details and how to consume them: docs/export.md.
// Pure C++ (no GL), so the CLI and the editor's File menu share it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stop_token>
#include <string>
#include <string_view>
#include <vector>

#include "project/project.h"
#include "scene/scene.h"
#include "util/result.h"

namespace grass::core {

enum class ExportFormat { Gltf, Raw, Glb, Mesh };

// LOD N keeps every 2^N-th live blade (blade_instances.h); 8 keeps one blade in 256, already
// far below anything a runtime would draw as a field.
inline constexpr int MAX_EXPORT_LOD = 8;

struct ExportOptions {
    ExportFormat format = ExportFormat::Gltf;
    int lod = 0;  // not raw: raw is the exact blade buffer, so it must be 0
    std::filesystem::path outDir;
    // --format mesh refuses more triangles than this (merged_blades.h).
    std::size_t maxMergedTriangles = 4'000'000;
    // A stop requested (the editor's Stop while it exports) ends the export at its next stage,
    // before its files are renamed into place: the folder stays as it was.
    std::stop_token stop;
    bool operator==(const ExportOptions&) const = default;
};

// "gltf" | "raw" | "glb" | "mesh"
std::string_view exportFormatName(ExportFormat format);
// Error (no path; the caller names the option): `unknown format "fbx" (gltf, raw, glb, mesh)`.
Result<ExportFormat> parseExportFormat(std::string_view name);

struct ExportedFile {
    std::filesystem::path path;  // inside outDir
    std::uint64_t bytes = 0;
};

struct ExportedLayer {
    std::string name;
    std::size_t liveBlades = 0;  // the layer's blades (padding and thinned slots left out)
    std::size_t instances = 0;   // what the export holds: glTF instances or raw slots
};

struct ExportReport {
    std::vector<ExportedFile> files;  // in the order written
    std::vector<ExportedLayer> layers;
    // What did not travel (a source texture on another UV set, ...), one line each.
    std::vector<std::string> notes;
    std::uint64_t totalBytes() const;
};

// Called with the share of the work done (0..1) and what is being done ("layer grass: blades").
using ExportProgress = std::function<void(float fraction, std::string_view stage)>;

// Writes the export into options.outDir (created if missing). Every file is written to a
// temporary name first and renamed into place only when all of them were written, so an error
// leaves the folder as it was (a folder it created is removed again). Errors name the file or
// the option ("lod", "outDir") and the problem.
Result<ExportReport> exportProject(const LoadedProject& loaded, const Scene& scene,
                                   const ExportOptions& options, const ExportProgress& progress);

// File names stay to characters safe in any file system and never form "..": a layer's name
// with anything else replaced by '_'.
std::string exportFileStem(const std::string& layerName);

// Refuses, before any work, an export whose entry points (<layer>.gltf, manifest.json) would
// replace one of the project's own files (project_inputs.h): an export into the project folder
// with a layer named like its mesh. exportProject checks it too, and refuses any file it would
// stage over an input.
Result<void> refuseExportOverInputs(const LoadedProject& loaded, const ExportOptions& options);

}  // namespace grass::core
