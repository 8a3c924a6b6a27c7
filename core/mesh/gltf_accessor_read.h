// One glTF accessor read into a flat array of components, with every check the file format
// allows (types per attribute, ranges against the buffer view and buffer, strides, sparse
// substitution, counts that would allocate beyond what the data can hold), shared by the glTF
// readers of core/mesh (gltf_accessors.cpp: primitives and instances; gltf_pose_accessors.cpp:
// skins and morph targets). Errors carry no path.
#pragma once

#include <tiny_gltf.h>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "util/result.h"

namespace grass::core::gltf {

// What a primitive reads, and so which accessor types it accepts.
enum class Semantic {
    Position,
    Normal,
    TexCoord,
    Indices,
    Translation,
    Rotation,
    Scale,
    Color,
    Joints,
    Weights,
    InverseBindMatrices
};

// OpenMesh indexes vertices with int.
inline constexpr std::uint64_t MAX_VERTICES =
    static_cast<std::uint64_t>(std::numeric_limits<int>::max());

// Components of an accessor type: SCALAR 1 … VEC4 4, MAT4 16; 0 for MAT2 and MAT3 (never read).
int typeComponents(int type);

// The accessor a primitive's attribute `name` uses; -1 when it has none.
int attributeAccessor(const tinygltf::Primitive& primitive, const std::string& name);

// "accessor 3 (POSITION of mesh "Leaf" primitive 0)": how messages name an accessor.
std::string accessorLabel(int index, Semantic semantic, const std::string& where);

// Accessor `index` as flat components of T (float or std::uint32_t), for the given attribute.
template <class T>
Result<std::vector<T>> readAccessor(const tinygltf::Model& model, int index, Semantic semantic,
                                    const std::string& where);

extern template Result<std::vector<float>> readAccessor<float>(const tinygltf::Model&, int,
                                                               Semantic, const std::string&);
extern template Result<std::vector<std::uint32_t>> readAccessor<std::uint32_t>(
    const tinygltf::Model&, int, Semantic, const std::string&);

}  // namespace grass::core::gltf
