//VTK::System::Dec
//=========================================================================
// ParticleSphereGS.glsl -- geometry stage of vtkParticleSphereMapper: one
// camera-facing triangle per particle (SphereImposter.glsl; for ellipsoids, PR_ELLIPSOID,
// one circumscribing the ellipsoid's silhouette). Invalid particles
// (radius <= 0, NaN or Inf) emit nothing. VTK's shader cache renames the
// fragment stage's *VSOutput inputs to the *GSOutput outputs written here.
// Hooks: //PR::Sphere::Dec (declarations, e.g. extra per-sphere inputs and
// outputs), //PR::Sphere::Cull (return to emit nothing for this sphere) and
// //PR::Sphere::Impl (per emitted vertex, e.g. copy extra outputs).
//=========================================================================
layout(points) in;
layout(triangle_strip, max_vertices = 3) out;

uniform mat4 VCDCMatrix;
uniform mat4 DCVCMatrix;
uniform int cameraParallel;
#if defined(PR_OCCLUSION_CULLING) || defined(PR_CONSERVATIVE_DEPTH)
// clip-space z and w of the MC->VC translation (see prDepthOfSplitPointVC)
uniform vec2 clipZWOfTranslation;
#endif

in vec4 centerRadiusVCVSOutput[];
in vec3 centerOffsetVCVSOutput[];
flat in int particleIdVSOutput[];
#ifdef PR_ELLIPSOID
flat in mat3 ellipsoidToVCVSOutput[];
flat in mat3 ellipsoidToUnitVSOutput[];
flat out mat3 ellipsoidToUnitGSOutput;
#endif

flat out vec4 centerRadiusVCGSOutput;
flat out vec3 centerOffsetVCGSOutput;
flat out int particleIdGSOutput;
out vec3 offsetVCGSOutput;
out vec3 rayVCGSOutput;

//VTK::Color::Dec
//VTK::Clip::Dec
//VTK::Picking::Dec
//VTK::PrimID::Dec

//PR::Include SphereImposter
#if defined(PR_OCCLUSION_CULLING) || defined(PR_CONSERVATIVE_DEPTH)
//PR::Include RaySphere
#endif
#ifdef PR_OCCLUSION_CULLING
//PR::Include OcclusionCull
#endif
//PR::Sphere::Dec

void main()
{
  vec3 centerVC = centerRadiusVCVSOutput[0].xyz;
  float radiusVC = centerRadiusVCVSOutput[0].w;
  if (!prSphereIsDrawable(centerVC, radiusVC))
  {
    return;
  }
  vec4 cornersDC[3];
  vec3 offsetsVC[3];
  vec3 raysVC[3];
  for (int corner = 0; corner < 3; ++corner)
  {
#ifdef PR_ELLIPSOID
    prEllipsoidBillboard(centerVC, ellipsoidToVCVSOutput[0], ellipsoidToUnitVSOutput[0], corner,
      cameraParallel != 0, VCDCMatrix, DCVCMatrix, cornersDC[corner], offsetsVC[corner],
      raysVC[corner]);
#else
    prSphereBillboard(centerVC, radiusVC, corner, cameraParallel != 0, VCDCMatrix, DCVCMatrix,
      cornersDC[corner], offsetsVC[corner], raysVC[corner]);
#endif
  }
#ifdef PR_OCCLUSION_CULLING
  // hidden behind the depth already drawn (vtkParticleOcclusionCuller)
  if (prSphereIsOccluded(cornersDC, centerOffsetVCVSOutput[0], radiusVC, clipZWOfTranslation,
        VCDCMatrix))
  {
    return;
  }
#endif
  //PR::Sphere::Cull
#ifdef PR_CONSERVATIVE_DEPTH
  // The triangle at the window depth of the sphere's nearest point (its largest view z, a
  // little beyond; on the near plane when that is in front of it), so that with the fragment
  // stage's depth_greater layout the depth test can reject hidden fragments before they run.
  // The split form keeps it below the written depths with the camera far away.
  vec2 prNearZW = prClipZWOfSplitPointVC(clipZWOfTranslation,
    centerOffsetVCVSOutput[0] + vec3(0.0, 0.0, 1.001 * radiusVC), VCDCMatrix);
  float prNearNDC = prNearZW.y > 0.0 ? max(prNearZW.x / prNearZW.y, -1.0) : -1.0;
  for (int corner = 0; corner < 3; ++corner)
  {
    cornersDC[corner].z = prNearNDC * cornersDC[corner].w;
  }
#endif
#ifdef PR_FLAT_DEPTH
  // every triangle at window depth 0.5 (never clipped by the near or far plane): for passes
  // that test against a mask in the depth buffer instead of depth (vtkMetaballWalkingPlane)
  for (int corner = 0; corner < 3; ++corner)
  {
    cornersDC[corner].z = 0.0;
  }
#endif
  int i = 0; // the input vertex, for VTK's pass-through replacements
  for (int corner = 0; corner < 3; ++corner)
  {
    gl_Position = cornersDC[corner];
    offsetVCGSOutput = offsetsVC[corner];
    rayVCGSOutput = raysVC[corner];
    centerRadiusVCGSOutput = centerRadiusVCVSOutput[0];
    centerOffsetVCGSOutput = centerOffsetVCVSOutput[0];
    particleIdGSOutput = particleIdVSOutput[0];
#ifdef PR_ELLIPSOID
    ellipsoidToUnitGSOutput = ellipsoidToUnitVSOutput[0];
#endif
    //VTK::PrimID::Impl
    //VTK::Color::Impl
    //VTK::Clip::Impl
    //VTK::Picking::Impl
    //PR::Sphere::Impl
    EmitVertex();
  }
  EndPrimitive();
}
