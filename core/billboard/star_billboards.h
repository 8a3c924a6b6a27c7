// Star billboard grass objects (SPEC §8, GPU Gems 1 ch. 7 "Rendering Countless Blades of Waving
// Grass"): each object is three vertical quads crossing at its centre, 60° apart, textured with
// an alpha grass texture. This file places objects on a surface, builds their vertices grouped
// by cluster, and holds the CPU side of the wind and the distance fade, which
// shaders/include/billboard_wind.glsl mirrors line for line. World space, metres, seconds.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "mesh/surface_mesh.h"
#include "scatter/surface_sampler.h"

namespace grass::core {

struct StarBillboardParams {
    float density = 40.0f;                 // objects per square metre of surface
    glm::vec2 heightRangeM{0.25f, 0.45f};  // object height, uniform in [x, y]
    float widthToHeight = 1.2f;            // quad width / quad height
    float clusterSizeM = 2.0f;             // edge of the cubic grid cells that form clusters
    bool operator==(const StarBillboardParams&) const = default;
};

struct GrassObject {
    glm::vec3 centre{0.0f};          // root on the surface
    glm::vec3 up{0.0f, 1.0f, 0.0f};  // unit; the quads' vertical edges follow it
    float height = 0.3f;             // metres
    float width = 0.36f;             // metres, of each quad
    float rotationRad = 0.0f;        // of the first quad about `up`
    std::uint32_t cluster = 0;       // index into StarMesh::clusters
    // Where it stands in the mesh's terms: UV0 (the painted maps' space) and the face.
    glm::vec2 uv{0.0f};
    std::uint32_t face = 0;
    // Uniform in [0, 1): the object lives where the near field keeps at least this share of its
    // blades (scene/billboard_follow.h), as a scattered blade lives where keep < density.
    float keep = 0.0f;
    // Multiplies the texture's colour: the near field's growth colour here against the colour
    // the texture stands for (1: as painted).
    glm::vec3 tint{1.0f};
    bool operator==(const GrassObject&) const = default;
};

// Objects uniform over the surface (area-weighted, SurfaceSampler), up = interpolated surface
// normal, height uniform in heightRangeM, rotation uniform in [0, 2π), keep from a hash of the
// seed and the object's placement index (not the placement stream, so it moved no object). The
// count is
// density × area rounded up or down at random (so its expectation is exactly density × area).
// Clusters: the cubic grid cells of edge clusterSizeM (≤ 0: one cluster) that hold at least one
// object, numbered in lexicographic cell order; objects are returned sorted by cluster (stable,
// placement order within a cluster). Deterministic for a given seed; empty for a mesh without
// area or density ≤ 0.
std::vector<GrassObject> placeGrassObjects(const SurfaceMesh& mesh,
                                           const StarBillboardParams& params, std::uint64_t seed);
// The same on a sampler of the mesh already made (Scene::sampler): the same objects.
std::vector<GrassObject> placeGrassObjects(const SurfaceSampler& sampler,
                                           const StarBillboardParams& params, std::uint64_t seed);

// One vertex of a star. Normal = up for every vertex (GPU Gems: normals parallel to the quads'
// vertical edges, so the three quads and both sides of each shade alike, like the grass they
// stand for). uv: u ∈ [0, 1] across the quad, v = 0 at the top vertices and 1 at the root
// (image convention: texture row 0, the top of the grass texture, is uploaded first).
struct StarVertex {
    glm::vec3 position{0.0f};
    glm::vec2 uv{0.0f};
    glm::vec3 normal{0.0f, 1.0f, 0.0f};
    glm::vec3 objectCentre{0.0f};
    float sway = 0.0f;  // 1 for the upper vertices (moved by the wind), 0 for the roots
    glm::vec3 tint{1.0f};       // the object's GrassObject::tint
    float objectHeight = 0.0f;  // metres: the animated normal and the scene wind's bend use it
};
static_assert(sizeof(StarVertex) == 64, "StarVertex is the GPU vertex layout, tightly packed");

inline constexpr std::uint32_t STAR_QUADS = 3;
// Four vertices per quad (lower left, lower right, upper right, upper left), twelve per object;
// starQuadIndices() turns each quad into two triangles: 18 indices per object.
inline constexpr std::uint32_t STAR_VERTICES_PER_OBJECT = 4 * STAR_QUADS;
inline constexpr std::uint32_t STAR_INDICES_PER_OBJECT = 6 * STAR_QUADS;

struct StarCluster {
    std::uint32_t firstVertex = 0;  // into StarMesh::vertices
    std::uint32_t vertexCount = 0;  // STAR_VERTICES_PER_OBJECT × objects; 0 for an empty cluster
    glm::vec3 centre{0.0f};         // mean of its objects' centres (wind phase, sort key)
    float radius = 0.0f;            // every vertex of the cluster lies within it of `centre`
};

// One star as the GPU draws it: billboard.vert makes its 12 vertices from the vertex id as
// starVertex() does (shaders/include/star_vertex.glsl), so a billboard takes 64 bytes of vertex
// data instead of 12 StarVertex (768): 1.66 million of them on a large terrain had 1.27 GB.
// The tint is split over the w components so that four vec4 attributes carry everything.
struct StarInstance {
    glm::vec3 centre{0.0f};
    float height = 0.0f;
    glm::vec3 up{0.0f, 1.0f, 0.0f};  // unit
    float tintR = 1.0f;
    glm::vec3 across0{0.0f};  // half the first quad's width, from the centre to its right edge
    float tintG = 1.0f;
    glm::vec3 across90{0.0f};  // across0 turned 90° about up
    float tintB = 1.0f;
};
static_assert(sizeof(StarInstance) == 64, "StarInstance is the GPU instance layout");

StarInstance starInstance(const GrassObject& object);
// Vertex `vertex` (0…STAR_VERTICES_PER_OBJECT − 1) of the star: quad vertex / 4 (turned by
// 60° each), corner vertex % 4 (bottom left, bottom right, top right, top left).
StarVertex starVertex(const StarInstance& star, std::uint32_t vertex);

// The stars sorted by cluster, and the clusters (firstVertex and vertexCount count the 12
// vertices each star stands for, as buildStarVertices lays them out).
struct StarInstances {
    std::vector<StarInstance> stars;
    std::vector<StarCluster> clusters;
};
StarInstances buildStarInstances(const std::vector<GrassObject>& objects);

struct StarMesh {
    std::vector<StarVertex> vertices;   // grouped contiguously by cluster, in cluster order
    std::vector<StarCluster> clusters;  // indexed by GrassObject::cluster
    std::size_t objectCount() const { return vertices.size() / STAR_VERTICES_PER_OBJECT; }
};

// Three quads at rotationRad + 0°, 60°, 120° about `up`, each width × height, bottom edge
// through the object's centre: buildStarInstances' stars, each expanded by starVertex. Objects
// keep their input order within a cluster. The cluster table has max(cluster) + 1 entries.
StarMesh buildStarVertices(const std::vector<GrassObject>& objects);

// Triangle indices for `objectCount` consecutive objects of buildStarVertices' layout, 32-bit
// (one object's: the 12 vertex ids of an instanced star).
std::vector<std::uint32_t> starQuadIndices(std::size_t objectCount);

// The editor's reduced picture draws one object in keepEvery (as blades keep one in n): of the
// objects [first, first + count), those whose index is a multiple of keepEvery, as a run of the
// list of every keepEvery-th object (entry j is object j·keepEvery).
struct KeptObjects {
    std::uint32_t first = 0;
    std::uint32_t count = 0;
};
KeptObjects keptObjects(std::uint32_t first, std::uint32_t count, std::uint32_t keepEvery);

// The animation modes of GPU Gems ch. 7 (values are the shader's uWindMode).
enum class BillboardWindMode : int {
    PerCluster = 0,  // one offset per cluster, computed here on the CPU; one draw per cluster
    PerVertex = 1,   // each upper vertex by its own rest position; one draw
    PerObject = 2,   // each upper vertex by its object's centre; one draw
};

struct BillboardWind {
    glm::vec2 directionXZ{1.0f, 0.0f};  // where the wind blows to, horizontal (normalised here)
    float amplitudeM = 0.05f;           // largest displacement of an upper vertex
    float frequencyHz = 0.5f;           // of the main sway
    bool operator==(const BillboardWind&) const = default;
};

// Horizontal offset of an upper vertex whose phase point is `p` (cluster centre, vertex or object
// centre) at timeS: a main sway along the wind (a travelling wave, sin) plus a smaller cross sway
// (cos at another frequency). |offset| ≤ amplitudeM, zero when amplitudeM is 0; y is always 0.
// shaders/include/billboard_wind.glsl has the same function.
glm::vec3 billboardWindOffset(glm::vec3 p, float timeS, const BillboardWind& wind);

// Distance fade: ramps 0 → 1 over [inStartM, inEndM] and 1 → 0 over [outStartM, outEndM] of the
// camera distance (smoothstep; an empty ramp is a step). Billboards as the far LOD behind the
// geometric blades fade in over the distances where the blades fade out.
struct BillboardFade {
    float inStartM = 0.0f;
    float inEndM = 0.0f;
    float outStartM = 1.0e30f;
    float outEndM = 1.0e30f;
    bool operator==(const BillboardFade&) const = default;
};
float billboardFade(float distanceM, const BillboardFade& fade);

}  // namespace grass::core
