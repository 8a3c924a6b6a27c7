// The text of `grass paint --stroke`: surface points of a brush stroke as "x,y,z; x,y,z; ..."
// (world units) or "u,v; ..." (UV space), and the repeated --stroke options themselves.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "util/result.h"

namespace grass::cli {

// ArgParser keeps one value per option, but strokes repeat: takes every "--stroke TEXT" and
// "--stroke=TEXT" out of `args` (which keeps the rest) and returns their texts in order.
Result<std::vector<std::string>> takeStrokes(std::vector<std::string>& args);

// One stroke's text: points separated by ';', each `dims` (3 or 2) comma-separated finite
// numbers; 2 numbers give z = 0. A trailing ';' is allowed, an empty point elsewhere is a typo.
// Errors name --stroke, the stroke (strokeNumber, 1-based) and the point.
Result<std::vector<glm::vec3>> parseStroke(const std::string& text, std::size_t strokeNumber,
                                           int dims);

}  // namespace grass::cli
