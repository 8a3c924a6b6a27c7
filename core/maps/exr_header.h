// A look at an OpenEXR file's header before OpenImageIO opens it. OpenEXR 3.1 allocates what an
// attribute's size field claims before it reads the value, so a damaged 400-byte file whose
// "capDate" claims 1.8 GB made the map loader allocate 1.8 GB (found by the map_exr fuzz
// target). Here every attribute's size is checked against the bytes the file has left, and
// the data window against the map size limit, without allocating either.
#pragma once

#include <filesystem>

#include "util/result.h"

namespace grass::core {

// True when the file starts with the OpenEXR magic number (76 2f 31 01); false when not or
// when it cannot be read.
bool hasExrMagic(const std::filesystem::path& file);

// For a file with the OpenEXR magic number: walks every header (one, or the parts of a
// multi-part file; OpenEXR file layout: name\0 type\0 int32 size, value; a header ends with an
// empty name) and fails, naming the file and the attribute, when a name runs past 255
// characters, an attribute's size is negative or beyond the end of the file, the header is
// cut short, or a dataWindow (box2i) is empty or wider or taller than maxSide.
Result<void> checkExrHeader(const std::filesystem::path& file, int maxSide);

}  // namespace grass::core
