//VTK::System::Dec
//=========================================================================
// ParticleSphereGS.glsl -- geometry stage of vtkParticleSphereMapper: one
// camera-facing triangle per particle (SphereImposter.glsl). Invalid particles
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

in vec4 centerRadiusVCVSOutput[];
in vec3 centerOffsetVCVSOutput[];
flat in int particleIdVSOutput[];

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
//PR::Sphere::Dec

void main()
{
  vec3 centerVC = centerRadiusVCVSOutput[0].xyz;
  float radiusVC = centerRadiusVCVSOutput[0].w;
  if (!prSphereIsDrawable(centerVC, radiusVC))
  {
    return;
  }
  //PR::Sphere::Cull
  int i = 0; // the input vertex, for VTK's pass-through replacements
  for (int corner = 0; corner < 3; ++corner)
  {
    prSphereBillboard(centerVC, radiusVC, corner, cameraParallel != 0, VCDCMatrix, DCVCMatrix,
      gl_Position, offsetVCGSOutput, rayVCGSOutput);
    centerRadiusVCGSOutput = centerRadiusVCVSOutput[0];
    centerOffsetVCGSOutput = centerOffsetVCVSOutput[0];
    particleIdGSOutput = particleIdVSOutput[0];
    //VTK::PrimID::Impl
    //VTK::Color::Impl
    //VTK::Clip::Impl
    //VTK::Picking::Impl
    //PR::Sphere::Impl
    EmitVertex();
  }
  EndPrimitive();
}
