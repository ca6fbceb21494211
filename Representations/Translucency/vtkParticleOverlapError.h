/**
 * @class   vtkParticleOverlapError
 * @brief   how wrong the sorted spheres can be where translucent spheres penetrate: the pairs
 *          whose lens may be off by more than a tolerance, and the pixels they cover in a view
 *
 * Where spheres i and j overlap, the sorted path composites one of them whole in front of the
 * other; the exact path integrates the summed densities. Along a ray the two differ only by the
 * order of the light emitted inside the lens the spheres share: with a_i, a_j the opacities of
 * the ray's parts inside the lens and L_i, L_j the emitted colours (vtkTransparentSphereMapper's
 * Eq. 2: constant along each sphere's chord), putting either part fully in front changes the
 * result by a_i a_j |L_i - L_j|, and the exact result lies between the two. So per pair
 *
 *   A_ij = a_i a_j max_channel |L_i - L_j|,   a_k = 1 - exp(-kappa_k min(1, l / (I_max R_k)))
 *
 * bounds the error of every pixel of the pair's lens, where l is the longest chord through the
 * lens (its width along the centre line, d = R_i + R_j - |p_i - p_j|, or its circle's diameter
 * 2 a, at most the smaller diameter), kappa_k = -ln(1 - Theta_k) the sphere's optical depth and
 * I_max R_k the largest density integral of its model (vtkTransparentSphereMapper::
 * GetMaximumPathIntegral): kappa / (I_max R) bounds the optical depth per unit length of both
 * density models (the squared-distance density is largest on the rim, where lenses are). The
 * emitted colours are not known before shading: |L_i - L_j| <= |c_i - c_j| + S, with the shading
 * range S = (1 - VolumeMix) 255 (Diffuse max(c) / 255 + Specular) of the lit part.
 *
 * Build keeps the pairs with A_ij above the tolerance (the only ones that can put a pixel over
 * it) that penetrate by more than a floor (a fraction of the smaller radius); EstimatePixels
 * sums the pixels their lenses can cover in a view (discs of radius max(a, d / 2) projected at
 * the pair's depth, the total at most the viewport); a lens behind the camera or wholly outside
 * the view frustum's side planes (its bounding sphere beyond one of them) counts nothing.
 * Occlusion by other geometry is not subtracted, nor are lenses counted once where they overlap
 * on screen: the estimate errs towards exact.
 *
 * Plain C++ (no VTK object), thread-safe after Build.
 */
#ifndef vtkParticleOverlapError_h
#define vtkParticleOverlapError_h

#include "vtkParticleRenderingTranslucencyModule.h" // for export macro
#include "vtkType.h"                                // for vtkIdType

#include <vector> // for std::vector

class vtkRenderer;

class VTKPARTICLERENDERINGTRANSLUCENCY_EXPORT vtkParticleOverlapError
{
public:
  struct Sphere
  {
    double Centre[3];
    double Radius;       // drawn radius (RadiusScaleFactor applied)
    double OpticalDepth; // kappa = -ln(1 - Theta), > 0
    double Colour[3];    // 0..255
  };

  /**
   * Find the penetrating pairs of `spheres` (all drawn and translucent) whose A_ij exceeds
   * `tolerance` (1/255 units) and whose penetration exceeds `floor` times the smaller radius.
   * `pathIntegral` is I_max for a sphere of radius 1, `shadingRange` S.
   */
  void Build(const std::vector<Sphere>& spheres, double pathIntegral, double shadingRange,
    double tolerance, double floor);

  /**
   * The number of pixels the kept pairs' lenses can cover in the renderer's current view (its
   * camera and tiled viewport size), at most the viewport's pixels.
   */
  double EstimatePixels(vtkRenderer* ren) const;

  /**
   * The same for an explicit view: eye position, unit view direction, view-up (need not be
   * orthogonal to the direction), pixels per world unit at distance 1 along the direction
   * (perspective: height / (2 tan(angle / 2)); parallel projection: pass parallel true and
   * height / (2 parallel scale)), and the viewport's size in pixels.
   */
  double EstimatePixels(const double eye[3], const double direction[3], const double up[3],
    double pixelsPerUnit, bool parallel, int width, int height) const;

  /**
   * Kept pairs, and the largest A_ij over all penetrating pairs (1/255).
   */
  vtkIdType GetNumberOfPairs() const { return static_cast<vtkIdType>(this->Lenses.size()); }
  double GetLargestAmplitude() const { return this->LargestAmplitude; }

  /**
   * A_ij of one pair (exposed for tests); 0 when they do not penetrate.
   */
  static double Amplitude(const Sphere& a, const Sphere& b, double pathIntegral,
    double shadingRange, double* lensRadius = nullptr, double* lensCentre = nullptr);

private:
  struct Lens
  {
    double Centre[3];
    double Radius;
  };
  std::vector<Lens> Lenses;
  double LargestAmplitude = 0.0;
};

#endif
