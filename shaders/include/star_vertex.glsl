// A star billboard's vertex from its instance (core::StarInstance, four vec4 attributes) and the
// vertex id 0…11: quad id / 4, turned by 60° each, corner id % 4 (bottom left, bottom right, top
// right, top left). The twin of core::starVertex (core/billboard/star_billboards.cpp), held
// together by tests/gl/billboard_motion_gl_test.cpp. `widthScale` widens the star about its
// centre (the editor's reduced picture draws one object in n, √n wider).
#ifndef STAR_VERTEX_GLSL
#define STAR_VERTEX_GLSL

struct StarVertex {
    vec3 position;
    vec2 uv;
    vec3 up;  // the object's up: every vertex's normal at rest
    vec3 centre;
    float sway;  // 1 for the upper vertices (moved by the wind), 0 for the roots
    vec3 tint;
    float height;
};

const vec2 STAR_QUAD_TURN[3] = vec2[3](vec2(1.0, 0.0), vec2(0.5, 0.8660254), vec2(-0.5, 0.8660254));

StarVertex starVertex(vec4 centreHeight, vec4 upTintR, vec4 across0TintG, vec4 across90TintB,
                      int vertex, float widthScale) {
    const vec2 turn = STAR_QUAD_TURN[(vertex / 4) % 3];
    const int corner = vertex % 4;
    const vec3 across = (turn.x * across0TintG.xyz + turn.y * across90TintB.xyz) * widthScale;
    const bool right = corner == 1 || corner == 2;
    const bool top = corner >= 2;
    StarVertex v;
    v.position = centreHeight.xyz + (right ? across : -across) +
                 (top ? upTintR.xyz * centreHeight.w : vec3(0.0));
    v.uv = vec2(right ? 1.0 : 0.0, top ? 0.0 : 1.0);
    v.up = upTintR.xyz;
    v.centre = centreHeight.xyz;
    v.sway = top ? 1.0 : 0.0;
    v.tint = vec3(upTintR.w, across0TintG.w, across90TintB.w);
    v.height = centreHeight.w;
    return v;
}

#endif
