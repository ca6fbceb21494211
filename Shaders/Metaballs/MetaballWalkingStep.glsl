//=========================================================================
// MetaballWalkingStep.glsl -- the step of the walking depth plane (Mueller,
// Grottel, Ertl 2007, Sec. 3.2.3), one full-viewport pass of
// vtkMetaballWalkingPlane. Reads the summed density (D(lambda), dD/dlambda,
// D(lambda + Delta_max), active count) and returns what is added to the plane
// (lambda step, 0, finished, 0); inactive pixels are discarded by the caller
// (and not counted by its occlusion query).
//=========================================================================
uniform float prIsoValue;          // t
uniform float prDepthTolerance;    // finished: Newton's distance to the surface below this
uniform float prDensityTolerance;  // finished where the field does not rise: |D/t - 1| below this
uniform float prMaximumStep;       // Delta_max
uniform int prOracle;              // 0: the paper's, 1: Newton within the bracket

vec4 prWalkingStep(vec4 density)
{
  float value = density.x;
  float slope = density.y;
  float d = value / prIsoValue;
  if (slope > 0.0 ? abs(prIsoValue - value) <= prDepthTolerance * slope
                  : abs(d - 1.0) <= prDensityTolerance)
  {
    return vec4(0.0, 0.0, 1.0, 0.0);
  }
  // the paper's: behind the surface back with linear attenuation, in front forward with
  // quadratic attenuation
  float step = d > 1.0 ? -0.5 * prMaximumStep * (d - 1.0) : prMaximumStep * (1.0 - d * d);
  if (prOracle != 0)
  {
    // Newton's step where the field rises with depth, kept within one largest step; in front
    // of the surface, without a crossing up to Delta_max ahead (the sample there is below t)
    // and no Newton step inside that, the full step
    float newton = slope > 0.0 ? (prIsoValue - value) / slope : 0.0;
    if (d > 1.0)
    {
      // behind the surface: Newton back where the field rises with depth; where it falls, the
      // plane is inside, past a maximum, and the crossing lies before that maximum: half a
      // largest step back (the paper's attenuation would creep back by (d - 1) / 2)
      step = slope > 0.0 ? max(newton, -prMaximumStep) : -0.5 * prMaximumStep;
    }
    else if (density.z >= prIsoValue)
    {
      // a crossing within Delta_max: Newton, or the secant to the far sample
      step = (slope > 0.0 && newton < prMaximumStep)
        ? newton
        : prMaximumStep * (prIsoValue - value) / (density.z - value);
    }
    else
    {
      step = (slope > 0.0 && newton < prMaximumStep) ? newton : prMaximumStep;
    }
  }
  return vec4(step, 0.0, 0.0, 0.0);
}
