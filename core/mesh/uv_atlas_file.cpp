#include "mesh/uv_atlas_file.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "util/atomic_file.h"
#include "util/rng.h"

namespace grass::core {

namespace {

constexpr std::string_view MAGIC = "GRASSUV1";
constexpr std::size_t HEADER_BYTES = 8 + 4 + 8;
constexpr std::size_t FACE_BYTES = 3 * 2 * 4;
// Positions are rounded to this fraction of the bounds before hashing: coarse enough that a
// re-export's float noise keeps the fingerprint, fine enough that any visible edit changes it.
constexpr double FINGERPRINT_ROUNDING = 1e-5;

void putU32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}
void putU64(std::string& out, std::uint64_t v) {
    for (int i = 0; i < 8; ++i)
        out.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
}
std::uint64_t getLe(const std::string& in, std::size_t at, int bytes) {
    std::uint64_t v = 0;
    for (int i = 0; i < bytes; ++i)
        v |= static_cast<std::uint64_t>(
                 static_cast<unsigned char>(in[at + static_cast<std::size_t>(i)]))
             << (8 * i);
    return v;
}

std::string meshChanged(const std::string& detail) {
    return "the mesh changed since the UV atlas was made (" + detail +
           "); generate the atlas again (maps painted on the old one no longer line up)";
}

}  // namespace

std::uint64_t meshFingerprint(const SurfaceMesh& mesh) {
    const Bounds bounds = meshBounds(mesh);
    const glm::dvec3 size = bounds.size();
    const double extent = std::max({size.x, size.y, size.z});
    const double quantum =
        extent > 0.0 && std::isfinite(extent) ? extent * FINGERPRINT_ROUNDING : 1.0;
    std::uint64_t hash = Rng::splitMix(static_cast<std::uint64_t>(mesh.n_faces()));
    for (const auto fh : mesh.faces()) {
        for (const glm::vec3& p : facePositions(mesh, fh)) {
            const glm::dvec3 q = (glm::dvec3(p) - glm::dvec3(bounds.min)) / quantum;
            for (int axis = 0; axis < 3; ++axis) {
                // Out of range of an integer (non-finite or absurd): one fixed value.
                const double c = q[axis];
                const std::int64_t r =
                    std::isfinite(c) && std::abs(c) < 9e18 ? std::llround(c) : INT64_MIN;
                hash = Rng::splitMix(hash ^ static_cast<std::uint64_t>(r));
            }
        }
    }
    return hash;
}

Result<void> saveUvAtlas(const std::filesystem::path& file, const CornerUvs& uvs,
                         std::uint64_t fingerprint) {
    if (uvs.size() > UINT32_MAX)
        return makeError(file.string(), "too many faces for a UV atlas file");
    std::string bytes(MAGIC);
    bytes.reserve(HEADER_BYTES + uvs.size() * FACE_BYTES);
    putU32(bytes, static_cast<std::uint32_t>(uvs.size()));
    putU64(bytes, fingerprint);
    for (const auto& face : uvs) {
        for (const glm::vec2& uv : face) {
            putU32(bytes, std::bit_cast<std::uint32_t>(uv.x));
            putU32(bytes, std::bit_cast<std::uint32_t>(uv.y));
        }
    }
    return writeFileAtomic(file, bytes);
}

Result<CornerUvs> loadUvAtlas(const std::filesystem::path& file, const SurfaceMesh& mesh) {
    const Result<std::string> read = readFile(file);
    if (!read)
        return read.error();
    const std::string& bytes = *read;
    const auto fail = [&](std::string message) { return makeError(file.string(), message); };
    if (bytes.size() >= MAGIC.size() && std::string_view(bytes).substr(0, MAGIC.size()) != MAGIC)
        return fail("not a UV atlas file (bad magic: it does not start with \"GRASSUV1\")");
    if (bytes.size() < HEADER_BYTES)
        return fail("truncated UV atlas: " + std::to_string(bytes.size()) +
                    " bytes, shorter than its " + std::to_string(HEADER_BYTES) + "-byte header");
    const std::uint64_t faces = getLe(bytes, 8, 4);
    const std::uint64_t fingerprint = getLe(bytes, 12, 8);
    const std::uint64_t expected = HEADER_BYTES + faces * FACE_BYTES;
    if (bytes.size() < expected)
        return fail("truncated UV atlas: " + std::to_string(bytes.size()) + " bytes, " +
                    std::to_string(expected) + " expected for " + std::to_string(faces) + " faces");
    if (bytes.size() > expected)
        return fail(
            "not a UV atlas this version wrote: " + std::to_string(bytes.size() - expected) +
            " bytes after the UVs of " + std::to_string(faces) + " faces");
    if (faces != mesh.n_faces())
        return fail(meshChanged("the atlas has " + std::to_string(faces) + " faces, the mesh has " +
                                std::to_string(mesh.n_faces())));
    if (fingerprint != meshFingerprint(mesh))
        return fail(meshChanged("its geometry fingerprint differs"));
    CornerUvs uvs(static_cast<std::size_t>(faces));
    std::size_t at = HEADER_BYTES;
    for (std::size_t f = 0; f < uvs.size(); ++f) {
        for (std::size_t k = 0; k < 3; ++k) {
            const auto u = std::bit_cast<float>(static_cast<std::uint32_t>(getLe(bytes, at, 4)));
            const auto v =
                std::bit_cast<float>(static_cast<std::uint32_t>(getLe(bytes, at + 4, 4)));
            at += 8;
            if (!std::isfinite(u) || !std::isfinite(v))
                return fail("face " + std::to_string(f) + " corner " + std::to_string(k) +
                            ": UV is not finite");
            uvs[f][k] = glm::vec2(u, v);
        }
    }
    return uvs;
}

}  // namespace grass::core
