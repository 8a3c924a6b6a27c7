#include "growth/growth_stems.h"

#include <algorithm>
#include <cmath>

namespace grass::core {

namespace {

int clampedLevels(int levels) {
    return std::clamp(levels, 1, MAX_STEM_LEVELS);
}

// Stem k's side and spread: stems 0–2 to −x, 3–5 to +x; within a side the spreads grow and the
// z spread alternates, so no two stems of a set coincide.
struct StemLayout {
    float side;
    float spreadX;
    float spreadZ;
};

StemLayout stemLayout(const StemSetParams& params, int stem) {
    const int k = std::clamp(stem, 0, STEMS_PER_SET - 1);
    const float side = k < 3 ? -1.0f : 1.0f;
    const float rank = static_cast<float>(k % 3);  // 0, 1, 2
    const float zSign = (k % 2 == 0) ? 1.0f : -1.0f;
    return {side, side * params.spreadX * rank * 0.5f, zSign * params.spreadZ * (rank + 1.0f) / 3.0f};
}

}  // namespace

std::vector<glm::vec3> stemLevelPoints(const StemSetParams& params, int stem) {
    const StemLayout layout = stemLayout(params, stem);
    const int levels = clampedLevels(params.levels);
    const float c = std::cos(params.theta), s = std::sin(params.theta);
    std::vector<glm::vec3> points{glm::vec3(0.0f)};
    float y = 0.0f, z = 0.0f, betaPower = 1.0f;
    for (int i = 1; i <= levels; ++i) {
        betaPower *= params.beta;
        const float grown = y + betaPower;
        const float nextY = grown * c - z * s;
        const float nextZ = grown * s + z * c + layout.spreadZ;
        y = nextY;
        z = nextZ;
        points.emplace_back(layout.side * params.alpha * 0.5f + layout.spreadX, y, z);
    }
    return points;
}

glm::vec3 clampedBSpline(const std::vector<glm::vec3>& controls, float u) {
    const int n = static_cast<int>(controls.size());
    if (n == 0)
        return glm::vec3(0.0f);
    if (n == 1)
        return controls.front();
    const int degree = std::min(3, n - 1);
    // Clamped uniform knots: degree + 1 zeros, the interior steps, degree + 1 ones.
    const int spans = n - degree;
    std::vector<float> knots;
    for (int i = 0; i <= degree; ++i)
        knots.push_back(0.0f);
    for (int i = 1; i < spans; ++i)
        knots.push_back(static_cast<float>(i) / static_cast<float>(spans));
    for (int i = 0; i <= degree; ++i)
        knots.push_back(1.0f);
    u = std::clamp(u, 0.0f, 1.0f);
    int span = degree;
    while (span < n - 1 && u >= knots[static_cast<std::size_t>(span + 1)])
        ++span;
    // De Boor's algorithm on the degree + 1 controls of the span.
    std::vector<glm::vec3> d(static_cast<std::size_t>(degree + 1));
    for (int j = 0; j <= degree; ++j)
        d[static_cast<std::size_t>(j)] = controls[static_cast<std::size_t>(span - degree + j)];
    for (int r = 1; r <= degree; ++r)
        for (int j = degree; j >= r; --j) {
            const int i = span - degree + j;
            const float left = knots[static_cast<std::size_t>(i)];
            const float right = knots[static_cast<std::size_t>(i + degree - r + 1)];
            const float a = right > left ? (u - left) / (right - left) : 0.0f;
            d[static_cast<std::size_t>(j)] =
                (1.0f - a) * d[static_cast<std::size_t>(j - 1)] + a * d[static_cast<std::size_t>(j)];
        }
    return d[static_cast<std::size_t>(degree)];
}

std::vector<glm::vec3> stemRibbon(const StemSetParams& params, int stem, float halfWidth,
                                  float tipWidth) {
    const std::vector<glm::vec3> controls = stemLevelPoints(params, stem);
    const int samples = STEM_SAMPLES_PER_LEVEL * clampedLevels(params.levels);
    std::vector<glm::vec3> ribbon;
    ribbon.reserve(static_cast<std::size_t>(2 * samples));
    for (int i = 0; i < samples; ++i) {
        const float u = static_cast<float>(i) / static_cast<float>(samples - 1);
        const glm::vec3 p = clampedBSpline(controls, u);
        const float w = halfWidth * (1.0f - (1.0f - tipWidth) * u);
        ribbon.emplace_back(p.x - w, p.y, p.z);
        ribbon.emplace_back(p.x + w, p.y, p.z);
    }
    return ribbon;
}

std::vector<glm::vec3> stemSetVertices(const StemSetParams& params, float halfWidth,
                                       float tipWidth) {
    std::vector<glm::vec3> vertices;
    for (int k = 0; k < STEMS_PER_SET; ++k) {
        const auto ribbon = stemRibbon(params, k, halfWidth, tipWidth);
        vertices.insert(vertices.end(), ribbon.begin(), ribbon.end());
    }
    return vertices;
}

}  // namespace grass::core
