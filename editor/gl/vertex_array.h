// VertexArray: a vertex array object (DSA, labelled), which the core profile needs bound for
// every draw: vertex attributes read from one interleaved vertex buffer on binding 0, and an
// element buffer for indexed draws. A draw that fetches nothing (vertices built from
// gl_VertexID, blades read from SSBOs) binds one with no attributes.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "gl/gl_handle.h"
#include "gl/gl_ref.h"

namespace grass::gl {

// Attribute i of the list is shader location i: `components` values of `type` at `offsetBytes`
// into the vertex; normalised integers arrive in 0..1.
struct VertexAttribute {
    int components;
    std::size_t offsetBytes;
    GLenum type = GL_FLOAT;
    bool normalised = false;
};

class VertexArray {
public:
    VertexArray() = default;  // none: create with the label
    explicit VertexArray(std::string_view label);

    // Locations 0..n−1 of `attributes`, all fed from vertex buffer binding 0.
    void setAttributes(std::span<const VertexAttribute> attributes);
    // The buffer on binding 0, `strideBytes` per vertex.
    void setVertexBuffer(BufferRef vertices, std::size_t strideBytes);
    // Binding 0 advances once per `divisor` instances instead of per vertex (0: per vertex).
    void setInstanceDivisor(GLuint divisor);
    void setElementBuffer(BufferRef indices);
    void bind() const { glBindVertexArray(mHandle.id()); }

private:
    VertexArrayHandle mHandle;
};

}  // namespace grass::gl
