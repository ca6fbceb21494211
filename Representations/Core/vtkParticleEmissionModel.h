/**
 * @class   vtkParticleEmissionModel
 * @brief   the GL-free emission-absorption model of a sphere glyph
 *
 * vtkParticleEmissionModel holds the parts of the transparent-sphere model of Staib, Grottel and
 * Gumhold 2015 ("Visualization of Particle-based Data with Transparency and Ambient Occlusion",
 * Sec. 3.1 and 4, Eq. 8-19) that more than one technique needs and that need no OpenGL:
 *
 * - the density models (Sec. 4): CONSTANT_DENSITY, rho = 1 (Eq. 13-15), and
 *   SQUARED_DISTANCE_DENSITY, rho = |x - p_i|^2 (Eq. 16-19), with a hollow core of the fraction f
 *   of the radius (Sec. 4.3, rho = 0 inside it);
 * - GetMaximumPathIntegral(): the maximum over all rays of the density integral through a unit
 *   sphere, I_max, which sets lambda so that the most opaque ray has the particle's opacity
 *   Theta_i (vtkTransparentSphereMapper's class comment derives it);
 * - MeanDiscOpacity(): the opacity averaged over the projected disc, the occupancy of a sphere
 *   in an ambient volume (vtkParticleAmbientVolume, the voxel-cone tracing of Sec. 6).
 *
 * vtkTransparentSphereMapper draws with this model; the ambient-occlusion volumes use it to
 * weigh a particle's occlusion by its translucency. Everything is double precision and static.
 *
 * @sa vtkTransparentSphereMapper vtkParticleAmbientVolume vtkParticleSphereMapper
 */
#ifndef vtkParticleEmissionModel_h
#define vtkParticleEmissionModel_h

#include "vtkObject.h"
#include "vtkParticleRenderingCoreModule.h" // for export macro

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleEmissionModel : public vtkObject
{
public:
  static vtkParticleEmissionModel* New();
  vtkTypeMacro(vtkParticleEmissionModel, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum DensityModels
  {
    CONSTANT_DENSITY = 0,
    SQUARED_DISTANCE_DENSITY = 1
  };

  /**
   * The maximum over all rays of the density integral through a sphere of radius 1: 2 sqrt(1 - f^2)
   * for CONSTANT_DENSITY; for SQUARED_DISTANCE_DENSITY 2 sqrt(2) / 3 when f <= 1/sqrt(2), else
   * 2 sqrt(1 - f^2) (1 + 2 f^2) / 3. f is clamped to [0, 0.999]. For a sphere of radius r multiply
   * by r (constant) or r^3 (squared distance).
   */
  static double GetMaximumPathIntegral(int densityModel, double hollowFraction);

  /**
   * The mean opacity over the projected disc of a sphere whose most opaque ray has opacity
   * theta, for a density model and a hollow core of the given fraction of the radius: closed
   * form for a solid constant-density sphere, 16-point Gauss-Legendre quadrature otherwise.
   * 0 for theta <= 0 or NaN, 1 for theta >= 1.
   */
  static double MeanDiscOpacity(double theta, int densityModel, double hollowFraction);

protected:
  vtkParticleEmissionModel() = default;
  ~vtkParticleEmissionModel() override = default;

private:
  vtkParticleEmissionModel(const vtkParticleEmissionModel&) = delete;
  void operator=(const vtkParticleEmissionModel&) = delete;
};

#endif
