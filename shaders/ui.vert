#version 450 core
// UI meshes (ui/mesh.h, drawn by editor/gl/ui_renderer): positions in points, y down from the
// top-left; colours premultiplied sRGB (normalised bytes).
layout(location = 0) in vec2 aPosPt;
layout(location = 1) in vec2 aUv;
layout(location = 2) in vec4 aColor;

// Framebuffer size in points (pixels / pixels per point).
uniform vec2 uScreenSizePt;

out vec2 vUv;
out vec4 vColor;

void main() {
    vUv = aUv;
    vColor = aColor;
    // Points to clip space: x right, y flipped because the UI's y runs down.
    vec2 ndc = vec2(2.0 * aPosPt.x / uScreenSizePt.x - 1.0, 1.0 - 2.0 * aPosPt.y / uScreenSizePt.y);
    gl_Position = vec4(ndc, 0.0, 1.0);
}
