#include "blade/bezier.h"

#include <cmath>

namespace grass::core {

glm::vec3 bezierPoint(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, float v) {
    const float a = 1.0f - v;
    return a * a * p0 + 2.0f * a * v * p1 + v * v * p2;
}

glm::vec3 bezierTangent(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, float v) {
    return 2.0f * (1.0f - v) * (p1 - p0) + 2.0f * v * (p2 - p1);
}

float bezierArcLength(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) {
    // B'(v) = 2(a·v + b) with a = p0 − 2p1 + p2, b = p1 − p0. |B'|² = 4(A v² + B v + C).
    // Done in double: the closed form cancels badly for nearly straight curves.
    const glm::dvec3 a = glm::dvec3(p0) - 2.0 * glm::dvec3(p1) + glm::dvec3(p2);
    const glm::dvec3 b = glm::dvec3(p1) - glm::dvec3(p0);
    const double A = glm::dot(a, a);
    const double B = 2.0 * glm::dot(a, b);
    const double C = glm::dot(b, b);
    if (A < 1e-18)
        return static_cast<float>(2.0 * std::sqrt(C));  // straight, uniform speed
    // A nearly collinear curve (discriminant ~ 0) folds back on itself: integrate numerically.
    const double disc = 4.0 * A * C - B * B;
    if (disc <= 1e-12 * A * A + 1e-30) {
        // 64-point composite Simpson on |B'|; exact enough (< 1e-6 rel) for a blade.
        const int n = 64;
        double sum = 0.0;
        for (int i = 0; i <= n; ++i) {
            const double v = static_cast<double>(i) / n;
            const double speed = 2.0 * std::sqrt(std::max(A * v * v + B * v + C, 0.0));
            sum += speed * (i == 0 || i == n ? 1.0 : (i % 2 ? 4.0 : 2.0));
        }
        return static_cast<float>(sum / (3.0 * n));
    }
    // L = 2·[F(1) − F(0)], F(x) = (2Ax + B)·√Q/(4A) + (4AC − B²)/(8A^1.5)·ln(2√A·√Q + 2Ax + B),
    // the standard antiderivative of √Q, Q(x) = Ax² + Bx + C.
    const double sqrtA = std::sqrt(A);
    const auto antiderivative = [&](double x) {
        const double sqrtQ = std::sqrt(std::max(A * x * x + B * x + C, 0.0));
        return (2.0 * A * x + B) * sqrtQ / (4.0 * A) +
               disc / (8.0 * A * sqrtA) * std::log(2.0 * sqrtA * sqrtQ + 2.0 * A * x + B);
    };
    const double length = 2.0 * (antiderivative(1.0) - antiderivative(0.0));
    return static_cast<float>(length);
}

float bezierLengthEstimate(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2) {
    const float l0 = glm::length(p2 - p0);
    const float l1 = glm::length(p2 - p1) + glm::length(p1 - p0);
    constexpr float n = 2.0f;
    return (2.0f * l0 + (n - 1.0f) * l1) / (n + 1.0f);
}

}  // namespace grass::core
