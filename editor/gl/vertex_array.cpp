#include "gl/vertex_array.h"

namespace grass::gl {

VertexArray::VertexArray(std::string_view label) {
    GLuint id = 0;
    glCreateVertexArrays(1, &id);
    mHandle = VertexArrayHandle(id);
    mHandle.setLabel(label);
}

void VertexArray::setAttributes(std::span<const VertexAttribute> attributes) {
    for (GLuint i = 0; i < attributes.size(); ++i) {
        const VertexAttribute& attribute = attributes[i];
        glEnableVertexArrayAttrib(mHandle.id(), i);
        glVertexArrayAttribFormat(mHandle.id(), i, attribute.components, attribute.type,
                                  attribute.normalised ? GL_TRUE : GL_FALSE,
                                  static_cast<GLuint>(attribute.offsetBytes));
        glVertexArrayAttribBinding(mHandle.id(), i, 0);
    }
}

void VertexArray::setVertexBuffer(BufferRef vertices, std::size_t strideBytes) {
    glVertexArrayVertexBuffer(mHandle.id(), 0, vertices.id(), 0, static_cast<GLsizei>(strideBytes));
}

void VertexArray::setInstanceDivisor(GLuint divisor) {
    glVertexArrayBindingDivisor(mHandle.id(), 0, divisor);
}

void VertexArray::setElementBuffer(BufferRef indices) {
    glVertexArrayElementBuffer(mHandle.id(), indices.id());
}

}  // namespace grass::gl
