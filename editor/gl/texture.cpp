#include "gl/texture.h"

namespace grass::gl {

TextureHandle makeTexture2D(GLenum internalFormat, int width, int height, int levels,
                            std::string_view label) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &id);
    TextureHandle texture(id);
    glTextureStorage2D(id, levels, internalFormat, width, height);
    texture.setLabel(label);
    return texture;
}

TextureHandle makeBufferTexture(GLenum internalFormat, GLuint buffer, std::string_view label) {
    GLuint id = 0;
    glCreateTextures(GL_TEXTURE_BUFFER, 1, &id);
    TextureHandle texture(id);
    glTextureBuffer(id, internalFormat, buffer);
    texture.setLabel(label);
    return texture;
}

void setClampedFiltering(TextureRef texture, GLenum minFilter, GLenum magFilter) {
    glTextureParameteri(texture.id(), GL_TEXTURE_MIN_FILTER, static_cast<GLint>(minFilter));
    glTextureParameteri(texture.id(), GL_TEXTURE_MAG_FILTER, static_cast<GLint>(magFilter));
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(texture.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void uploadTexture2D(TextureRef texture, int width, int height, GLenum format, const void* pixels) {
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, format, GL_UNSIGNED_BYTE, pixels);
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
}

}  // namespace grass::gl
