// 2D textures with immutable storage (glTextureStorage2D), created with DSA and labelled, and
// the upload of tightly packed pixel rows into them.
#pragma once

#include <string_view>

#include "gl/gl_handle.h"
#include "gl/gl_ref.h"

namespace grass::gl {

// `levels` mip levels of `internalFormat` (GL_RGBA8, GL_DEPTH_COMPONENT32F, ...), the base level
// width × height; the contents are undefined until uploaded or rendered.
TextureHandle makeTexture2D(GLenum internalFormat, int width, int height, int levels,
                            std::string_view label);

// A buffer texture over all of `buffer` (GL_TEXTURE_BUFFER), texels of `internalFormat`
// (GL_RGBA32F, GL_R32UI, ...): shaders read it with texelFetch. It follows the buffer's
// contents; the buffer must outlive it and keep its storage.
TextureHandle makeBufferTexture(GLenum internalFormat, GLuint buffer, std::string_view label);

// Minification and magnification filters, and clamp-to-edge in s and t: the textures here are
// sprites, atlases and depth maps, none of which may repeat across its edge.
void setClampedFiltering(TextureRef texture, GLenum minFilter, GLenum magFilter);

// Writes width × height pixels of `format` bytes (GL_RGBA, GL_RED, ...) into level 0, rows
// tightly packed (unpack alignment 1 for the call), row 0 at t = 0.
void uploadTexture2D(TextureRef texture, int width, int height, GLenum format, const void* pixels);

}  // namespace grass::gl
