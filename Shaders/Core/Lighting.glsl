//=========================================================================
// Lighting.glsl -- VTK's Phong light model (vtkOpenGLPolyDataMapper, VTK 9.2)
// as functions. The light uniforms are the ones vtkOpenGLRenderer sets
// (lightColorN = diffuse colour * intensity, lightDirectionVCN = direction the
// light travels, in view coordinates). vtkParticleReferenceRenderer evaluates
// the same formulas in double precision.
//
// n: unit surface normal (VC); p: surface point (VC). The view vector of the
// specular term is VTK's normalize(-p), towards the camera position, in
// perspective and in parallel projection alike (VTK 9.2's shader does this,
// checked by TestVTKShadingComparison against VTK's own shading), and the
// specular base is clamped to at least 1e-5 as in VTK.
//=========================================================================

// Light complexity 1: a single headlight, L = V = H = +z.
void prHeadlight(vec3 n, vec3 lightColor, float specularPower, inout vec3 diffuse,
  inout vec3 specular)
{
  float df = max(0.000001, n.z);
  diffuse += df * lightColor;
  specular += pow(df, specularPower) * lightColor;
}

// Light complexities 2 (directional) and 3 (positional and spot lights).
void prSceneLight(vec3 n, vec3 p, vec3 lightColor, vec3 lightDirectionVC,
  int positional, vec3 positionVC, vec3 attenuationCoefficients, float coneAngle,
  float exponent, float specularPower, inout vec3 diffuse, inout vec3 specular)
{
  float attenuation = 1.0;
  vec3 l = lightDirectionVC;
  if (positional != 0)
  {
    l = p - positionVC;
    float distanceVC = length(l);
    l = l / distanceVC;
    attenuation = 1.0 /
      (attenuationCoefficients.x + attenuationCoefficients.y * distanceVC +
        attenuationCoefficients.z * distanceVC * distanceVC);
    if (coneAngle < 90.0)
    {
      float coneDot = dot(l, lightDirectionVC);
      attenuation = coneDot >= cos(radians(coneAngle)) ? attenuation * pow(coneDot, exponent) : 0.0;
    }
  }
  float df = max(0.0, attenuation * dot(n, -l));
  diffuse += df * lightColor;
  float sf =
    sign(df) * attenuation * pow(max(1e-5, dot(reflect(l, n), normalize(-p))), specularPower);
  specular += sf * lightColor;
}
