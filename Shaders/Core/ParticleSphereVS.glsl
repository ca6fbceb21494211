//VTK::System::Dec
//=========================================================================
// ParticleSphereVS.glsl -- vertex stage of vtkParticleSphereMapper: one
// invocation per particle (GL_POINTS, plain vertex attributes), the view-space
// sphere for the geometry stage (ParticleSphereGS.glsl), which emits its
// billboard triangle.
// The //VTK:: tags are filled by vtkOpenGLPolyDataMapper and by render passes,
// the //PR:: tags are hooks for ParticleRendering passes and subclasses:
//   //PR::Sphere::Dec / //PR::Sphere::Impl  per-sphere work (this stage runs
//   once per sphere, e.g. per-sphere ambient-occlusion fetches); centerVC and
//   radiusVC are set.
// PR_ELLIPSOID (vtkParticleSphereMapper's Shape ELLIPSOID): the particle is an
// oriented ellipsoid (EllipsoidFrame.glsl); radiusVC is the radius of a sphere
// that contains it.
//=========================================================================
in vec4 vertexMC;
in float radiusMC;

// MC->VC radius factor: user scale factor times the actor's scale
uniform float radiusScaleVC;
uniform mat4 MCVCMatrix;

//VTK::CustomUniforms::Dec
//VTK::Color::Dec
//VTK::Clip::Dec
//VTK::Picking::Dec
//VTK::ValuePass::Dec

out vec4 centerRadiusVCVSOutput;
// the centre without the MC->VC translation (see prDepthOfSplitPointVC in RaySphere.glsl)
out vec3 centerOffsetVCVSOutput;
flat out int particleIdVSOutput;
#ifdef PR_ELLIPSOID
// semi-axes (model coordinates) and unit quaternion (w, x, y, z) of the body frame
in vec3 axesMC;
in vec4 orientationMC;
// the linear part of the model -> view map times the radius scale factor, and its inverse
uniform mat3 axesToVC;
uniform mat3 vcToAxes;
flat out mat3 ellipsoidToVCVSOutput;
flat out mat3 ellipsoidToUnitVSOutput;
//PR::Include EllipsoidFrame
#endif

//PR::Sphere::Dec

void main()
{
  particleIdVSOutput = gl_VertexID;

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
#ifdef PR_ELLIPSOID
  prEllipsoidFrame(axesMC, orientationMC, axesToVC, vcToAxes, ellipsoidToVCVSOutput,
    ellipsoidToUnitVSOutput, radiusVC);
#endif
  centerRadiusVCVSOutput = vec4(centerVC, radiusVC);
  //PR::Sphere::Impl
  //VTK::CustomEnd::Impl
}
