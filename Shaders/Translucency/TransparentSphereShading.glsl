//=========================================================================
// TransparentSphereShading.glsl -- the translucent fragment of
// vtkTransparentSphereMapper (Staib et al. 2015): the opacity of the visible
// part of a sphere's chord from its optical depth (EmissionAbsorption.glsl)
// and the colour of Eq. 2, premultiplied, for front-to-back compositing.
//
// Uniforms (declared by the mapper before this file): prVolumeMix (alpha_RV),
// prActorOpacity (the actor's opacity and transmittance from the CPU in
// double, x < 0 when scalar alpha applies), prCullMode (0: opaque particles
// are drawn by the opaque stage), prMaximumIntegral (I_max),
// prHollowFraction2, prOpaqueDepth (the opaque image's depth texture); and
// from the sphere template clipZWOfTranslation and VCDCMatrix.
//=========================================================================
//PR::Include EmissionAbsorption

// The visible part of a sphere's chord in a translucent fragment, in units of the radius from
// the ray's closest approach to the centre: kappa the optical depth of the particle's most opaque
// ray (< 0: opaque), b2 the squared impact parameter, the chord [-h, h], the visible segment
// [tn, tf] (clipN / clipF: moved by clipping), radiance the colour it emits (Eq. 2); scale the
// view-coordinate length of one unit of tau along this ray and closest the view-coordinate
// offset of tau = 0 from the centre (for the exact-overlap lists).
// Ellipsoids (PR_ELLIPSOID): the same in the ellipsoid's unit frame (the unit sphere under
// x = c + A u, EllipsoidFrame.glsl): b2 and the chord are the unit sphere's, one unit of tau is
// 1 / |A^-1 d| along this ray, and kappa is scaled by 1 / (|A^-1 d| a_max) -- the optical depth
// of a physical density integrated over view-coordinate length, normalised so that the particle's
// most opaque ray is its longest axis a_max (radiusVC): Theta_i is the opacity along that axis.
struct prSegment
{
  float kappa;
  float b2;
  float h;
  float tn;
  float tf;
  bool clipN;
  bool clipF;
  vec3 radiance;
  float scale;
  vec3 closest;
};

// kappaA: the particle's optical depth (< 0: opaque, Theta_a = 1); opacity: VTK's fragment
// opacity; litColor: the lit surface colour L_R; diffuseColor: the material colour c_i;
// ambientOcclusion and ambientLight: A_O and alpha_A L_A of an AO pass at the entry point
// (1 and 0 without one), applied as Eq. 7: A_O L_RV + alpha_A L_A; the ray
// (rayS relative to the centre, unit rayD) with both hits t0 < t1; radiusVC; centerOffsetVC:
// the centre without the MC->VC translation. Returns false when the fragment adds nothing (or
// belongs to the opaque stage).
bool prTranslucentSegment(float kappaA, float opacity, vec3 litColor, vec3 diffuseColor,
  float ambientOcclusion, vec3 ambientLight, vec3 rayS, vec3 rayD, float t0, float t1, float radiusVC, vec3 centerOffsetVC,
  out prSegment seg)
{
  seg = prSegment(0.0, 0.0, 0.0, 0.0, 0.0, false, false, vec3(0.0), 0.0, vec3(0.0));
  // Theta_i = Theta_a * opacity, as an optical depth: the actor's opacity and transmittance
  // from the CPU in double when the opacity is the actor's alone (no scalar alpha), else
  // from VTK's opacity
  float thetaO = prActorOpacity.x >= 0.0 ? prActorOpacity.x : opacity;
  float tauO = prActorOpacity.x >= 0.0 ? prActorOpacity.y : 1.0 - opacity;
  float thetaA = kappaA < 0.0 ? 1.0 : prOneMinusExpNeg(kappaA);
  float tauA = kappaA < 0.0 ? 0.0 : exp(-kappaA);
  float kappa = (tauO == 0.0 && kappaA >= 0.0) ? kappaA
    : prCombinedOpticalDepth(thetaA, tauA, thetaO, tauO);
  if ((kappa < 0.0 && prCullMode == 0) || kappa == 0.0)
  {
    return false; // opaque (drawn in the opaque stage), or clear
  }
  // the visible part of the chord, as fractions u of [entry, exit]: clip space is affine along
  // the ray, so each bound (in front of the eye, near and far planes, in front of the opaque
  // depth) is a linear inequality in u
  vec2 zw0 = prClipZWOfSplitPointVC(clipZWOfTranslation, centerOffsetVC + rayS + t0 * rayD,
    VCDCMatrix);
  vec2 zw1 = prClipZWOfSplitPointVC(clipZWOfTranslation, centerOffsetVC + rayS + t1 * rayD,
    VCDCMatrix);
  float opaqueDepth = texelFetch(prOpaqueDepth, ivec2(gl_FragCoord.xy), 0).r;
  float opaqueNDC =
    (2.0 * opaqueDepth - gl_DepthRange.near - gl_DepthRange.far) / gl_DepthRange.diff;
  vec2 bounds[4] =
    vec2[4](vec2(0.0, 1.0), vec2(1.0, 1.0), vec2(-1.0, 1.0), vec2(-1.0, opaqueNDC));
  float un = 0.0;
  float uf = 1.0;
  for (int k = 0; k < 4; ++k)
  {
    float g0 = dot(bounds[k], zw0);
    float g1 = dot(bounds[k], zw1);
    if (g0 < 0.0 && g1 < 0.0)
    {
      return false;
    }
    if (g0 < 0.0)
    {
      un = max(un, g0 / (g0 - g1));
      seg.clipN = true;
    }
    else if (g1 < 0.0)
    {
      uf = min(uf, g0 / (g0 - g1));
      seg.clipF = true;
    }
  }
  // the radiance of a sphere entered at its surface is that of the whole sphere (Eq. 2), also
  // where the clip box of distributed rendering (ClipBox.glsl) cuts its chord into parts that
  // other processes draw: sum_k T_k theta_k c = theta c, so the parts composite exactly
  bool enteredInside = seg.clipN;
#ifdef PR_CLIP_BOX
  if (!prClipSegmentToBox(rayS + t0 * rayD, rayS + t1 * rayD, un, uf, seg.clipN, seg.clipF))
  {
    return false;
  }
#endif
  if (!(uf > un))
  {
    return false;
  }
  seg.kappa = kappa;
#ifdef PR_ELLIPSOID
  vec3 su = ellipsoidToUnitVSOutput * rayS;
  vec3 du = ellipsoidToUnitVSOutput * rayD;
  float unitPerVC = length(du);
  du /= unitPerVC;
  float tc = -dot(su, du);
  seg.h = 0.5 * (t1 - t0) * unitPerVC;
  vec3 q = su + tc * du;
  seg.b2 = min(1.0, dot(q, q));
  seg.scale = 1.0 / unitPerVC;
  seg.closest = rayS + (tc / unitPerVC) * rayD;
  if (kappa > 0.0)
  {
    seg.kappa = kappa / (unitPerVC * radiusVC);
  }
#else
  seg.h = 0.5 * (t1 - t0) / radiusVC;
  vec3 q = rayS - dot(rayS, rayD) * rayD;
  seg.b2 = min(1.0, dot(q, q) / (radiusVC * radiusVC));
  seg.scale = radiusVC;
  seg.closest = q;
#endif
  seg.tn = -seg.h + 2.0 * seg.h * un;
  seg.tf = -seg.h + 2.0 * seg.h * uf;
  // Eq. 2: surface reflection at the entry point mixed with the volume colour, occluded and lit
  // by the ambient terms there (Eq. 7); without an entry surface (the segment starts inside)
  // only the volume emits, and there is no front hit for the ambient terms
  seg.radiance = enteredInside ? diffuseColor
    : ambientOcclusion * mix(litColor, diffuseColor, prVolumeMix) + ambientLight;
  return true;
}

// The premultiplied colour (theta * radiance, theta) of the fragment's segment alone, for
// front-to-back compositing of sorted spheres. Returns false when it adds nothing.
bool prShadeTranslucentSphere(float kappaA, float opacity, vec3 litColor, vec3 diffuseColor,
  float ambientOcclusion, vec3 ambientLight, vec3 rayS, vec3 rayD, float t0, float t1,
  float radiusVC, vec3 centerOffsetVC, out vec4 result)
{
  result = vec4(0.0);
  prSegment seg;
  if (!prTranslucentSegment(kappaA, opacity, litColor, diffuseColor, ambientOcclusion,
        ambientLight, rayS, rayD, t0, t1, radiusVC, centerOffsetVC, seg))
  {
    return false;
  }
  float integral =
    prSegmentIntegral(seg.b2, seg.h, seg.tn, seg.tf, seg.clipN, seg.clipF, prHollowFraction2);
  // kappa < 0: an opaque particle drawn here (the actor's opacity is not 1)
  float theta = seg.kappa < 0.0 ? (integral > 0.0 ? 1.0 : 0.0)
    : prSegmentOpacity(seg.kappa, integral, prMaximumIntegral);
  result = vec4(theta * seg.radiance, theta);
  return true;
}
