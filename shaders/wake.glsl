// The boat's Kelvin wake and its foam: the GLSL twin of src/sim/wake/kelvinWake.ts and
// src/sim/wake/wakeFoam.ts (read the method and its sources there). Keep the files in step. The
// uniforms are packed by packWakeUniforms (src/sim/wake/wakeUniformData.ts) and uploaded by
// src/render/wake/wakeUniforms.ts.
//
// Cost: a vertex within uWakeParams.z of the boat runs the loop over uWakeCount ≤ 64 track
// points (one sqrt, one exp, one division per point; two polynomial sines and one cosine
// per segment); anywhere else it returns after one dot product.

#define WAKE_TRACK_POINTS 64

// Newest first: (x − uWakeOrigin.x, z − uWakeOrigin.y, age in s, speed in m/s).
uniform vec4 uWakeTrack[WAKE_TRACK_POINTS];
uniform int uWakeCount;
// The reduced origin: the boat's latest position, world metres.
uniform vec2 uWakeOrigin;
// (C, σ, radius, g): amplitude constant (strength included; 0 = off), footprint radius,
// early-out distance from the origin, gravity.
uniform vec4 uWakeParams;
// History taper (start, end), seconds of age.
uniform vec2 uWakeTaper;
// (hull length, hull beam, trail decay s, bow decay s).
uniform vec4 uWakeFoam;

#include <oceano_sin_turns>

// One source: amplitude τ³/r⁴ · exp(−k²σ²/4) · taper, phase g τ²/(4r) in turns, and the
// derivatives of phase (radians per metre) and amplitude along x and z.
void wakeSource(vec2 p, vec4 s, float sigma, float g, out float amplitude, out float turns, out vec2 dPhase, out vec2 dAmplitude) {
  vec2 d = p - s.xy;
  float r2 = dot(d, d) + sigma * sigma;
  float r = sqrt(r2);
  float tau = s.z;
  float k = g * tau * tau / (4.0 * r2);
  float hullFilter = exp(-0.25 * k * k * sigma * sigma);
  float taper = 1.0 - smoothstep(uWakeTaper.x, uWakeTaper.y, tau);
  amplitude = tau * tau * tau / (r2 * r2) * hullFilter * taper;
  turns = k * r / TURN_RADIANS;
  dPhase = -k * d / r;
  dAmplitude = amplitude * (-4.0 + k * k * sigma * sigma) / r2 * d;
}

// (η, ∂η/∂x, ∂η/∂z) of the wake at world (x, z), metres.
vec3 wakeHeightAndGradient(vec2 worldXZ) {
  vec3 result = vec3(0.0);
  float c = uWakeParams.x;
  if (uWakeCount < 2 || c == 0.0) return result;
  vec2 p = worldXZ - uWakeOrigin;
  if (dot(p, p) > uWakeParams.z * uWakeParams.z) return result;
  float sigma = uWakeParams.y;
  float g = uWakeParams.w;
  float ampA;
  float turnsA;
  vec2 dPhaseA;
  vec2 dAmpA;
  wakeSource(p, uWakeTrack[0], sigma, g, ampA, turnsA, dPhaseA, dAmpA);
  for (int i = 1; i < WAKE_TRACK_POINTS; i++) {
    if (i >= uWakeCount) break;
    float ampB;
    float turnsB;
    vec2 dPhaseB;
    vec2 dAmpB;
    wakeSource(p, uWakeTrack[i], sigma, g, ampB, turnsB, dPhaseB, dAmpB);
    float dt = uWakeTrack[i].z - uWakeTrack[i - 1].z;
    float amplitude = 0.5 * (ampA + ampB) * dt * c;
    float midTurns = 0.5 * (turnsA + turnsB);
    float halfTurns = 0.5 * (turnsB - turnsA);
    float halfPhase = TURN_RADIANS * halfTurns;
    float sinc = abs(halfPhase) < 1e-4 ? 1.0 - halfPhase * halfPhase / 6.0 : sinTurns(halfTurns) / halfPhase;
    float wave = sinTurns(midTurns) * sinc;
    result.x += amplitude * wave;
    result.yz += amplitude * sinTurns(midTurns + 0.25) * sinc * 0.5 * (dPhaseA + dPhaseB) + 0.5 * dt * c * wave * (dAmpA + dAmpB);
    ampA = ampB;
    turnsA = turnsB;
    dPhaseA = dPhaseB;
    dAmpA = dAmpB;
  }
  return result;
}

float wakeHeight(vec2 worldXZ) {
  return wakeHeightAndGradient(worldXZ).x;
}

// Foam intensity in [0, 1] at world (x, z): hull trail and bow-wave lines (see wakeFoam.ts).
float wakeFoam(vec2 worldXZ) {
  if (uWakeCount < 2) return 0.0;
  vec2 p = worldXZ - uWakeOrigin;
  float hullLength = uWakeFoam.x;
  float halfBeam = 0.5 * uWakeFoam.y;
  float trail = 0.0;
  float bow = 0.0;
  for (int i = 1; i < WAKE_TRACK_POINTS; i++) {
    if (i >= uWakeCount) break;
    vec4 a = uWakeTrack[i - 1];
    vec4 b = uWakeTrack[i];
    vec2 e = b.xy - a.xy;
    float len2 = dot(e, e);
    if (len2 < 1e-8) continue;
    float along = dot(p - a.xy, e) / len2;
    if (i == 1 && along < 0.0) continue;
    float f = clamp(along, 0.0, 1.0);
    float d = length(p - (a.xy + e * f));
    float age = mix(a.z, b.z, f);
    float speed = abs(mix(a.w, b.w, f));
    float breaking = smoothstep(0.1, 0.35, speed / sqrt(uWakeParams.w * hullLength));
    if (breaking == 0.0) continue;
    float width = halfBeam * (1.0 + 0.1 * age);
    trail = max(trail, breaking * exp(-age / uWakeFoam.z) * exp(-0.5 * d * d / (width * width)));
    if (along < 0.0 || along > 1.0) continue;
    float bowAge = age + 0.5 * hullLength / max(speed, 1e-3);
    float offset = halfBeam + 0.36 * speed * bowAge;
    float bowWidth = 0.3 + 0.05 * speed * bowAge;
    float off = d - offset;
    bow = max(bow, breaking * exp(-bowAge / uWakeFoam.w) * exp(-0.5 * off * off / (bowWidth * bowWidth)));
  }
  return min(1.0, trail + bow);
}

// The normal of y = h_model + η from the model's unit normal n and the wake's slope
// (∂η/∂x, ∂η/∂z): the twin of addWake in src/sim/wake/boatWake.ts.
vec3 wakeTiltNormal(vec3 n, vec2 slope) {
  return normalize(vec3(n.x - slope.x * n.y, n.y, n.z - slope.y * n.y));
}
