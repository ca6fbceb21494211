//=========================================================================
// PointAO.glsl -- the occlusion of vtkPointAOPass (Eichelbaum et al. 2013,
// PointAO, Sec. 4, after LineAO Eqs. 1, 6-7). A full-screen pass over the
// G-buffer the delegate drew:
//   prDepth    window depth (1: background)
//   prNormal   the view-space normal times 3 + a where the geometry wrote one,
//              a the radius of a particle's sphere (0 for other geometry); a
//              shorter vector (the delegate's clear, geometry without normals):
//              the normal is taken from the depth buffer
//   prNormalDepth  the stamp of the fragment that wrote prNormal, its window
//              depth + prStampKey: the normal is used only where the stamp
//              equals prDepth + prStampKey (anything drawn over the opaque
//              geometry without a normal output, e.g. depth peeling's full-
//              screen quad, leaves undefined values in both targets)
// prPointAO(pixel) is the occlusion mean_j AO_j in [0, 1] (0: none), with
// AO_j = sum_i (1 - V_j(w_i)) <w_i, n> / sum_i <w_i, n> over the directions
// w_i, 1 - V_j(w) the part of the ray p + t w, t <= R_j, that is blocked (see
// vtkPointAOPass.h for the radius rule and the occlusion test). Every
// quantity is in view coordinates, so the result does not depend on the
// window size or the zoom.
//=========================================================================

uniform sampler2D prDepth;
uniform sampler2D prNormal;
uniform sampler2D prNormalDepth;
uniform float prStampKey;
uniform int prStoredNormals;      // 0: the normal targets were not drawn (see vtkPointAOPass)
uniform mat4 prProjection;        // view -> clip
uniform mat4 prInverseProjection; // clip -> view
uniform vec2 prSize;              // the G-buffer's pixels
uniform ivec2 prTargetSize;       // the occlusion texture's texels
uniform int prStep;               // G-buffer pixels per occlusion texel (1, or 2: half size)
uniform int prLevels;             // L
uniform int prSamples;            // samples of level 1 (level j: j prSamples)
uniform float prRadius;           // outermost radius, view units
uniform float prBaseRadius;       // r0
uniform int prDepthScaling;       // the paper's depth term on (1) or off (0)
uniform vec2 prClipRange;         // near and far distance along the view axis
uniform float prThickness;        // how deep the scene is taken to be behind o, view units
uniform float prHidden;           // P(a point behind a visible sphere lies in a hidden one)

vec3 prViewPosition(vec2 uv, float depth)
{
  vec4 v = prInverseProjection * vec4(vec3(uv, depth) * 2.0 - 1.0, 1.0);
  return v.xyz / v.w;
}

// a per-pixel pseudo-random value in [0, 1) (an integer hash of the pixel and a seed: no
// pattern that could beat with a crystal lattice)
float prPixelNoise(ivec2 pixel, uint seed)
{
  uint h = uint(pixel.x) * 1973u + uint(pixel.y) * 9277u + seed * 26699u;
  h = (h ^ (h >> 16u)) * 0x7feb352du;
  h = (h ^ (h >> 15u)) * 0x846ca68bu;
  h = h ^ (h >> 16u);
  return float(h >> 8u) * (1.0 / 16777216.0);
}

// The linear depth of p over the clipping range, 0 at the near plane, 1 at the far one.
float prLinearDepth(vec3 p)
{
  return clamp((-p.z - prClipRange.x) / max(prClipRange.y - prClipRange.x, 1e-30), 0.0, 1.0);
}

// The radius of the shell boundary after level j (R_0 = 0), before the depth term.
float prLevelRadius(int j)
{
  float L = float(prLevels);
  float fj = float(j);
  return prRadius * (fj * fj + fj * prBaseRadius) / (L * L + L * prBaseRadius);
}

float prPointAO(ivec2 pixel, out float viewDepth);

// The normal and sphere radius (0 for other geometry) the G-buffer holds for a pixel of window
// depth `depth`, when the fragment that wrote that depth wrote them (see prNormalDepth; the sum
// is rounded as the hooked fragment rounded it); false otherwise.
bool prStoredNormal(ivec2 pixel, float depth, out vec3 n, out float radius)
{
  n = vec3(0.0);
  radius = 0.0;
  if (prStoredNormals == 0 || texelFetch(prNormalDepth, pixel, 0).r != depth + prStampKey)
  {
    return false;
  }
  vec3 stored = texelFetch(prNormal, pixel, 0).xyz;
  float length3 = length(stored);
  if (!(length3 > 2.5) || isinf(length3))
  {
    return false;
  }
  n = stored / length3;
  radius = length3 - 3.0;
  return true;
}

// The window depth of a pixel, clamped to the G-buffer (texelFetch outside a texture is
// undefined).
float prDepthAt(ivec2 pixel)
{
  return texelFetch(prDepth, clamp(pixel, ivec2(0), ivec2(prSize) - 1), 0).r;
}

// (occlusion, view depth -z, 1) of a pixel with geometry, (0, 0, 0) of the background: what the
// blur (PointAOBlur.glsl) reads
vec4 prPointAOTarget(ivec2 texel)
{
  float z = 0.0;
  float occlusion = prPointAO(min(texel * prStep, ivec2(prSize) - 1), z);
  return z > 0.0 ? vec4(occlusion, z, 1.0, 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
}

float prPointAO(ivec2 pixel, out float viewDepth)
{
  viewDepth = 0.0;
  float depth = texelFetch(prDepth, pixel, 0).r;
  if (!(depth < 1.0))
  {
    return 0.0;
  }
  vec2 uv = (vec2(pixel) + 0.5) / prSize;
  vec3 p = prViewPosition(uv, depth);
  viewDepth = (isnan(p.z) || isinf(p.z)) ? 0.0 : max(-p.z, 1e-30);
  vec3 n;
  float own; // the pixel's sphere's radius, or 0
  if (!prStoredNormal(pixel, depth, n, own))
  {
    // no normal from the geometry: the depth buffer's (neighbours on the nearer side)
    vec2 dx = vec2(1.0 / prSize.x, 0.0);
    vec2 dy = vec2(0.0, 1.0 / prSize.y);
    vec3 px = prViewPosition(uv + dx, prDepthAt(pixel + ivec2(1, 0))) - p;
    vec3 mx = p - prViewPosition(uv - dx, prDepthAt(pixel - ivec2(1, 0)));
    vec3 py = prViewPosition(uv + dy, prDepthAt(pixel + ivec2(0, 1))) - p;
    vec3 my = p - prViewPosition(uv - dy, prDepthAt(pixel - ivec2(0, 1)));
    n = cross(abs(px.z) < abs(mx.z) ? px : mx, abs(py.z) < abs(my.z) ? py : my);
  }
  // facing the viewer (perspective: towards the eye; parallel: +z)
  vec3 toEye = prProjection[3][3] > 0.5 ? vec3(0.0, 0.0, 1.0) : -p;
  n = dot(n, toEye) < 0.0 ? -n : n;
  if (!(dot(n, n) > 0.0) || any(isnan(p)) || any(isinf(p)))
  {
    return 0.0;
  }
  n = normalize(n);
  // the centre of the pixel's own sphere: its surface is no occluder of its own points
  vec3 centre = p - own * n;
  // a frame around n, rotated by a per-pixel angle
  vec3 a = abs(n.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
  vec3 t = normalize(cross(a, n));
  vec3 b = cross(n, t);
  // interleaved over 4 x 4 pixels: 16 rotations of the direction set (a Bayer order), which
  // the blur averages where the surface is continuous
  const float order[16] = float[16](0.0, 8.0, 2.0, 10.0, 12.0, 4.0, 14.0, 6.0, 3.0, 11.0, 1.0,
    9.0, 15.0, 7.0, 13.0, 5.0);
  float cell = order[(pixel.x & 3) + 4 * (pixel.y & 3)];
  float angle = 6.2831853 * (cell + prPixelNoise(pixel, 1u)) / 16.0;
  float shift = fract(cell * 0.6180340 + 0.25 * prPixelNoise(pixel, 2u));
  vec3 t1 = cos(angle) * t + sin(angle) * b;
  vec3 b1 = cross(n, t1);
  float scale = prDepthScaling != 0 ? 1.0 / (1.0 - 0.5 * prLinearDepth(p)) : 1.0;

  // per direction (stratified in cos(theta), uniform in the solid angle; golden-ratio
  // azimuths) a ray through the levels: level j adds j points in its shell (R_{j-1}, R_j], so
  // level j has j prSamples samples (more outwards); occluded[j] sums the blocked part of the
  // rays up to R_j, summed over j in `occlusion` (the transmittance `open` only falls along a
  // ray)
  float occlusion = 0.0; // sum over the levels j of the blocked part of the rays up to R_j
  float weights = 0.0;
  for (int i = 0; i < prSamples; ++i)
  {
    float c = (float(i) + 0.5) / float(prSamples);
    float s = sqrt(max(0.0, 1.0 - c * c));
    float phi = 6.2831853 * fract(float(i) * 0.6180340);
    vec3 w = s * (cos(phi) * t1 + sin(phi) * b1) + c * n;
    float inner = 0.0;
    // the transmittance of the ray so far, per level
    float open = 1.0;
    bool onScreen = true;
    for (int j = 1; j <= prLevels; ++j)
    {
      float outer = scale * prLevelRadius(j);
      // j points, more where the shell is wider than the pixel's sphere (a ray must not step
      // over a particle: at most one radius apart), at most 4 j
      int steps = own > 0.0 ? clamp(int(ceil((outer - inner) / own)), j, 4 * j) : j;
      for (int k = 0; k < steps && open > 0.0 && onScreen; ++k)
      {
        float r = mix(inner, outer,
          (float(k) + fract(shift + float(i) * 0.7548777)) / float(steps));
        vec3 q = p + r * w;
        vec4 clip = prProjection * vec4(q, 1.0);
        vec2 quv = clip.xy / clip.w * 0.5 + 0.5;
        if (!(clip.w > 0.0) || any(lessThan(quv, vec2(0.0))) ||
          any(greaterThanEqual(quv, vec2(1.0))))
        {
          onScreen = false; // leaves the view: open from here on
          break;
        }
        ivec2 qp = ivec2(quv * prSize);
        float occluderDepth = texelFetch(prDepth, qp, 0).r;
        if (!(occluderDepth < 1.0))
        {
          continue;
        }
        // the visible surface at that pixel's centre (where its depth and normal were taken)
        vec3 o = prViewPosition((vec2(qp) + 0.5) / prSize, occluderDepth);
        float gap = o.z - q.z;
        if (!(gap > 0.02 * r) || length(o - centre) < 1.01 * own)
        {
          continue; // in front of the visible surface, or behind the pixel's own sphere
        }
        vec3 no;
        float a;
        prStoredNormal(qp, occluderDepth, no, a);
        if (a > 0.0)
        {
          // a particle: inside its sphere blocks; behind it, a hidden sphere blocks with the
          // probability prHidden while within the thickness
          if (length(q - (o - a * no)) < a)
          {
            open = 0.0;
          }
          else if (gap < prThickness * scale)
          {
            open *= 1.0 - prHidden;
          }
        }
        else if (gap < prThickness * scale)
        {
          open = 0.0; // other geometry: taken to be prThickness deep
        }
      }
      occlusion += c * (1.0 - open);
      inner = outer;
    }
    weights += c;
  }
  float result = weights > 0.0 ? occlusion / (weights * float(prLevels)) : 0.0;
  return (isnan(result) || isinf(result)) ? 0.0 : clamp(result, 0.0, 1.0);
}
