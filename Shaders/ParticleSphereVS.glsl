//VTK::System::Dec
//=========================================================================
// ParticleSphereVS.glsl -- vertex stage of vtkParticleSphereMapper.
// Vertex pulling: one non-instanced draw of 3 vertices (one triangle) per
// particle; particle i = gl_VertexID / 3 is fetched from buffer textures that
// alias the mapper's vertex buffers (centres with VTK's shift/scale, radii,
// colours). Real GPUs and llvmpipe both run this far better than 4-vertex
// instances or a geometry shader.
// The //VTK:: tags are filled by vtkOpenGLPolyDataMapper and by render passes,
// the //PR:: tags are hooks for ParticleRendering passes and subclasses:
//   //PR::Sphere::Dec / //PR::Sphere::Impl  per-sphere work in the vertex stage
//   (e.g. per-sphere ambient-occlusion fetches); centerVC and radiusVC are set.
//=========================================================================
uniform samplerBuffer prCenters;
uniform samplerBuffer prRadii;

// MC->VC radius factor: user scale factor times the actor's scale
uniform float radiusScaleVC;
uniform mat4 MCVCMatrix;
uniform mat4 VCDCMatrix;
uniform mat4 DCVCMatrix;
uniform int cameraParallel;

//VTK::CustomUniforms::Dec
//VTK::Color::Dec
//VTK::Clip::Dec
//VTK::Picking::Dec
//VTK::ValuePass::Dec

flat out vec4 centerRadiusVCVSOutput;
// the centre without the MC->VC translation (see prDepthOfSplitPointVC in RaySphere.glsl)
flat out vec3 centerOffsetVCVSOutput;
out vec3 offsetVCVSOutput;
flat out int particleIdVSOutput;

//PR::Include SphereImposter
//PR::Sphere::Dec

void main()
{
  int particleId = gl_VertexID / 3;
  int corner = gl_VertexID - 3 * particleId;
  vec4 vertexMC = vec4(texelFetch(prCenters, particleId).xyz, 1.0);
  float radiusMC = texelFetch(prRadii, particleId).r;
  particleIdVSOutput = particleId;

  //VTK::CustomBegin::Impl
  //VTK::Color::Impl
  //VTK::Clip::Impl
  //VTK::ValuePass::Impl
  //VTK::Picking::Impl

  // MCVCMatrix is affine: centre = rotation/scale part + translation, kept apart for the depth
  vec3 centerOffsetVC = mat3(MCVCMatrix) * vertexMC.xyz;
  vec3 centerVC = centerOffsetVC + MCVCMatrix[3].xyz;
  centerOffsetVCVSOutput = centerOffsetVC;
  float radiusVC = radiusMC * radiusScaleVC;
  centerRadiusVCVSOutput = vec4(centerVC, radiusVC);
  if (!prSphereIsDrawable(centerVC, radiusVC))
  {
    // invalid particle (radius <= 0, NaN or Inf): a degenerate triangle outside the
    // clip volume produces no fragment
    offsetVCVSOutput = vec3(0.0);
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    return;
  }
  prSphereBillboard(centerVC, radiusVC, corner, cameraParallel != 0, VCDCMatrix, DCVCMatrix,
    gl_Position, offsetVCVSOutput);
  //PR::Sphere::Impl
  //VTK::CustomEnd::Impl
}
