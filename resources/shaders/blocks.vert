#version 330 core
// One instance per block: the planar pose and the box's size arrive as
// per-instance attributes, so every block of the ladder is one draw call.
in vec3 vertexPosition;  // unit cube, -0.5 .. 0.5
in vec3 vertexNormal;
in vec4 blockPose;       // x, y (m), angle (rad), z of the centre (m)
in vec4 blockSize;       // across, along, out of the plane (m); w: highlight 0..1
in vec4 blockColor;      // linear-ish rgb, a unused

uniform mat4 viewProjectionMatrix;
uniform mat4 projectionMatrix;
uniform mat4 viewportMatrix;  // window from normalised coordinates: [1][1] is half the height in pixels

// A block seen from far off (a long ladder framed whole) would be thinner
// than a pixel and vanish: draw it at least this many pixels across.
const float kMinPixels = 1.5;

out vec3 worldPosition;
out vec3 worldNormal;
out vec3 localPosition;  // in metres, from the block's centre
out vec3 halfSize;
out vec3 localNormal;
out vec3 baseColor;
out float highlight;

void main() {
    vec4 centre = viewProjectionMatrix * vec4(blockPose.xy, blockPose.w, 1.0);
    float metresPerPixel = 2.0 * max(centre.w, 0.0) / (projectionMatrix[1][1] * max(2.0 * viewportMatrix[1][1], 1.0));
    vec3 size = max(blockSize.xyz, vec3(kMinPixels * metresPerPixel));
    vec3 p = vertexPosition * size;
    float c = cos(blockPose.z), s = sin(blockPose.z);
    vec3 w = vec3(c * p.x - s * p.y + blockPose.x, s * p.x + c * p.y + blockPose.y, p.z + blockPose.w);
    worldPosition = w;
    worldNormal = vec3(c * vertexNormal.x - s * vertexNormal.y, s * vertexNormal.x + c * vertexNormal.y, vertexNormal.z);
    localPosition = p;
    localNormal = vertexNormal;
    halfSize = 0.5 * size;
    baseColor = blockColor.rgb;
    highlight = blockSize.w;
    gl_Position = viewProjectionMatrix * vec4(w, 1.0);
}
