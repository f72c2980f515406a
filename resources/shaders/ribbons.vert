#version 330 core
// One instance per ribbon path of up to five points in the ladder's plane
// (a ribbon as the engine lays it: along a face, round an end, across to
// the next block's face); the shared mesh holds a quad per segment and
// lane, and each vertex says which segment, which end of it, which edge
// of the strip and which lane it is. So a frame uploads 40 bytes a ribbon,
// not the 24 vertices (48 for an outer pair) of 24 bytes of its quads.
in vec4 ribbonCorner;  // segment 0..3, end 0/1 along it, edge -1/1 across, lane -1/0/1
in vec4 ribbonFrom;    // points 0 and 1 (m)
in vec4 ribbonOn;      // points 2 and 3
in vec2 ribbonTo;      // point 4

uniform mat4 viewProjectionMatrix;
uniform float halfWidth;   // m, of each strip
uniform float laneOffset;  // m, from the blocks' middle plane to a lane's centre

out vec3 worldPosition;
out vec3 worldNormal;

void main() {
    vec2 points[5] = vec2[5](ribbonFrom.xy, ribbonFrom.zw, ribbonOn.xy, ribbonOn.zw, ribbonTo);
    int k = int(ribbonCorner.x);
    vec2 d = points[k + 1] - points[k];
    // A segment of no length (a path of fewer points, padded) draws nothing: its quad has no area.
    vec2 n = dot(d, d) > 0.0 ? normalize(vec2(-d.y, d.x)) : vec2(0.0, 1.0);
    vec2 xy = ribbonCorner.y > 0.5 ? points[k + 1] : points[k];
    worldPosition = vec3(xy, ribbonCorner.w * laneOffset + ribbonCorner.z * halfWidth);
    worldNormal = vec3(n, 0.0);
    gl_Position = viewProjectionMatrix * vec4(worldPosition, 1.0);
}
