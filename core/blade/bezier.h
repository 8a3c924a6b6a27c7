// Quadratic Bézier maths of the blade curve (SPEC §1, §3, §7): evaluation, tangent, exact arc
// length and the degree-n length estimate of Jahrmann §5.2. World units throughout.
#pragma once

#include <glm/glm.hpp>

namespace grass::core {

// B(v) = (1−v)²·p0 + 2(1−v)v·p1 + v²·p2, v in [0, 1].
glm::vec3 bezierPoint(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, float v);

// dB/dv = 2(1−v)(p1 − p0) + 2v(p2 − p1).
glm::vec3 bezierTangent(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, float v);

// Exact arc length of the quadratic (closed form, with the straight-line and degenerate cases).
float bezierArcLength(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2);

// Gravelius-style estimate the paper uses: L = (2·L0 + (n−1)·L1)/(n+1), n = 2,
// L0 = |p2 − p0| (chord), L1 = |p2 − p1| + |p1 − p0| (control polygon).
float bezierLengthEstimate(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2);

}  // namespace grass::core
