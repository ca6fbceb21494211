//VTK::System::Dec
//=========================================================================
// ParticleSphereFS.glsl -- fragment stage of vtkParticleSphereMapper: ray-cast
// sphere (or, with PR_ELLIPSOID, oriented ellipsoid: radiusVC then bounds it) with
// exact depth, lit with VTK's lights and material.
//
// Visible surface: the first ray/sphere intersection that lies in front of the
// eye and between the near and far planes. From outside that is the front
// surface; with the eye inside a sphere (or the near plane cutting it) it is the
// inner side of the back surface, shaded with the normal facing the viewer.
//
// Hooks (//PR:: tags) for ParticleRendering passes and subclasses, all present
// from the start (the contract, with the names in scope: vtkParticleShaderHooks.h):
//   //PR::Sphere::Dec             declarations (uniforms, samplers, functions)
//   //PR::Surface::Impl           after the intersection: may change prHit, prT0, prT1
//   //PR::Coverage::Impl          before a miss is discarded (prHit)
//   //PR::Surface::Normal         after the visible point: may change the normal
//   //PR::AmbientOcclusion::Impl  multiply prAmbientOcclusion (visibility in [0,1])
//                                 and add to prAmbientLight (radiance after occlusion)
//   //PR::Shading::Impl           replace the opaque result gl_FragData[0]
//                                 (e.g. an emission-absorption model); the ray
//                                 (prRayS, prRayD), both hits (prT0, prT1), the
//                                 centre and radius are in scope
//=========================================================================
uniform int PrimitiveIDOffset;
uniform mat4 VCDCMatrix;
uniform int cameraParallel;
// clip-space z and w of the MC->VC translation (see prDepthOfSplitPointVC)
uniform vec2 clipZWOfTranslation;
// picking: the drawn particle's index times this is the input point's (see MaximumNumberOfParticles)
uniform int particleIdStride;

flat in vec4 centerRadiusVCVSOutput;
flat in vec3 centerOffsetVCVSOutput;
in vec3 offsetVCVSOutput;
in vec3 rayVCVSOutput;
flat in int particleIdVSOutput;
#ifdef PR_ELLIPSOID
// view-coordinate offsets from the centre -> the unit sphere (EllipsoidFrame.glsl)
flat in mat3 ellipsoidToUnitVSOutput;
#endif

//VTK::CustomUniforms::Dec
//VTK::Color::Dec
//VTK::Normal::Dec
//VTK::Light::Dec
//VTK::TMap::Dec
//VTK::Picking::Dec
//VTK::DepthPeeling::Dec
//VTK::Clip::Dec
//VTK::Output::Dec
//VTK::Coincident::Dec
//VTK::ValuePass::Dec

//PR::Include RaySphere
//PR::Sphere::Dec

void main()
{
  vec3 centerVC = centerRadiusVCVSOutput.xyz;
  float radiusVC = centerRadiusVCVSOutput.w;

  // the fragment's ray, as a point relative to the centre and a unit direction
  vec3 prRayS = offsetVCVSOutput;
  vec3 prRayD = cameraParallel != 0 ? vec3(0.0, 0.0, -1.0) : normalize(rayVCVSOutput);
  float prT0;
  float prT1;
#ifdef PR_ELLIPSOID
  bool prHit = prIntersectEllipsoid(prRayS, prRayD, ellipsoidToUnitVSOutput, prT0, prT1);
#else
  bool prHit = prIntersectSphere(prRayS, prRayD, radiusVC, prT0, prT1);
#endif
  //PR::Surface::Impl
  //PR::Coverage::Impl
  if (!prHit)
  {
    discard;
  }
  // first visible intersection; the depth is computed from the MC->VC translation and the
  // small rest of the point separately (exact ordering with the camera far away)
  vec3 hitRel = prRayS + prT0 * prRayD;
  float depth;
  bool prInside = false;
  if (!prDepthOfSplitPointVC(clipZWOfTranslation, centerOffsetVCVSOutput + hitRel, VCDCMatrix, depth))
  {
    hitRel = prRayS + prT1 * prRayD;
    prInside = true;
    if (!prDepthOfSplitPointVC(clipZWOfTranslation, centerOffsetVCVSOutput + hitRel, VCDCMatrix, depth))
    {
      discard;
    }
  }
#ifndef PR_NO_DEPTH_WRITE
  gl_FragDepth = depth;
#endif
  vec4 vertexVC = vec4(centerVC + hitRel, 1.0);
#ifdef PR_ELLIPSOID
  vec3 normalVCVSOutput = prEllipsoidNormal(prInside ? -hitRel : hitRel, ellipsoidToUnitVSOutput);
#else
  vec3 normalVCVSOutput = (prInside ? -hitRel : hitRel) / radiusVC;
#endif
  //PR::Surface::Normal

  //VTK::PositionVC::Impl
  //VTK::UniformFlow::Impl
  //VTK::Depth::Impl
  //VTK::DepthPeeling::PreColor
  //VTK::Clip::Impl
  //VTK::ValuePass::Impl
  //VTK::Color::Impl
  //VTK::Normal::Impl
  // lighting (the mapper fills //PR::Lighting::Impl): prSurfaceColor, unless the result is
  // not a lit colour (e.g. normals for vtkLightingMapPass), written directly with prLit false
  bool prLit = true;
  vec3 prSurfaceColor = vec3(0.0);
  //PR::Lighting::Impl
  if (prLit)
  {
    float prAmbientOcclusion = 1.0;
    vec3 prAmbientLight = vec3(0.0);
    //PR::AmbientOcclusion::Impl
    gl_FragData[0] = vec4(prAmbientOcclusion * prSurfaceColor + prAmbientLight, opacity);
    //PR::Shading::Impl
  }
  // VTK's tag stays free for VTK passes and shader replacements, which act on the result
  //VTK::Light::Impl
  //VTK::TCoord::Impl

  if (gl_FragData[0].a <= 0.0)
  {
    discard;
  }
  // no NaN or Inf may reach the framebuffer
  if (any(isnan(gl_FragData[0])) || any(isinf(gl_FragData[0])))
  {
    discard;
  }
  //VTK::DepthPeeling::Impl
  //VTK::Picking::Impl
  //VTK::Coincident::Impl
}
