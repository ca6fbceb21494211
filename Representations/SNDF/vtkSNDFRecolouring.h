/**
 * @class   vtkSNDFRecolouring
 * @brief   a new colour map of vtkSNDFRenderPass's particles without taking the samples again
 *
 * vtkSNDFRenderPass's class description, "Colour (the colour map, the diffuse colours)": a bin
 * of the S-MIP (vtkSNDFTileCache) keeps the mean of its samples' AO * colour, which is linear
 * in the colours. Where the particles' new stored colours are a linear function of the old
 * ones, c' = M c for every particle, the cached bins' colours are multiplied by M
 * (RecolourLinear(); M fitted by least squares to the distinct (old, new) colour pairs,
 * FitColourMatrix(), AddPairs()). Any other new map of the colour coordinates
 * (vtkSNDFColourCoordinates) re-shades from the bins' moments: the old and the new ramp go to
 * Shaders/SNDF/SNDFRecolour.glsl (RecolourMap()), with the least-squares map between the ramps
 * carrying the old quadrature error (RampResidual()). Otherwise the samples are taken again.
 *
 * Colours holds what each particle actor's samples were taken with (kept at a restart or a
 * recolour, KeepColours()), Key what the pass's colour key was then. The fits and the pair
 * collection need no OpenGL. Plain C++ (no vtkObject); vtkSNDFRenderPass holds one.
 * TestSNDFRecolouring checks FitColourMatrix() and AddPairs() alone.
 *
 * @sa vtkSNDFRenderPass vtkSNDFColourCoordinates vtkSNDFTileCache
 */
#ifndef vtkSNDFRecolouring_h
#define vtkSNDFRecolouring_h

#include "vtkParticleRenderingSNDFModule.h" // for export macro
#include "vtkSNDFColourCoordinates.h"       // for vtkSNDFColourCoordinates::SampledColours
#include "vtkSmartPointer.h"                // for vtkSmartPointer

#include <array>  // for std::array
#include <vector> // for std::vector

class vtkActor;
class vtkOpenGLRenderWindow;
class vtkSNDFTileCache;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGSNDF_EXPORT vtkSNDFRecolouring
{
public:
  using SampledColours = vtkSNDFColourCoordinates::SampledColours;
  // an old and a new colour, three values each
  using Pair = std::array<double, 6>;

  vtkSNDFRecolouring(vtkSNDFTileCache* cache, vtkSNDFColourCoordinates* coordinates)
    : Cache(cache)
    , Coordinates(coordinates)
  {
  }

  // per particle actor (in the order of the view's props) the colours its samples hold
  std::vector<SampledColours> Colours;
  // the colour key they were taken with (the lookup tables' modification times, ...)
  std::vector<double> Key;

  /**
   * The 3 x 3 matrix M with M o = n for each pair (o, n) of `pairs`: least squares through the
   * pseudo-inverse of sum o o^T (minimum norm where the old colours span fewer than three
   * dimensions). False unless every pair is met within `tolerance` and no entry of M exceeds
   * 16 in magnitude (the bins' 16-bit mean colours are multiplied by it: at most
   * 16 * 3 * 2 / 65535 = 0.37 / 255 of quantisation error).
   */
  static bool FitColourMatrix(const std::vector<Pair>& pairs, double m[3][3], double tolerance);

  /**
   * What the diffuse colour of an actor's samples is (SampledColours) in the pass's material
   * modes 0 and 1 (`rawMaterial` 1: the shade applies the diffuse coefficient).
   */
  static SampledColours StoredColours(vtkActor* actor, int rawMaterial);

  /**
   * One actor's distinct (old, new) colour pairs in the units of the stored diffuse colour
   * appended to `pairs` (every actor's, the unchanged ones too: M must keep them); `changed` set
   * where its colours changed. False where no M can map them: the opacity changed, one old
   * colour has two new ones, more than 4096 distinct colours, the colours were mapped anew into
   * the same array, or a changed colour is carried by a colour-dependent light in the colour
   * target (the actor's `ambient` coefficient, or `coloured`: an object-space ambient light that
   * carries the particles' colours).
   */
  static bool AddPairs(const SampledColours& then, const SampledColours& now, double ambient,
    bool coloured, bool& changed, std::vector<Pair>& pairs);

  /**
   * The least-squares linear map from the old ramp's colours to the new one's (RGBA entries,
   * both centred); 0 where that has entries beyond +-16.
   */
  static void RampResidual(
    const std::vector<float>& oldRamp, const std::vector<float>& newRamp, double residual[3][3]);

  /**
   * The colours the particle actors' samples are taken with from now on (a restart, a
   * recolour); the ramp of the colour coordinates with them where the shader writes them.
   */
  void KeepColours(const std::vector<vtkActor*>& particles, int rawMaterial);

  /**
   * A new colour map: 0 where the mapped colours did not change, 1 where the cached bins were
   * recoloured (RecolourLinear(), else RecolourMap()), -1 where the samples must be taken again.
   */
  int Recolour(const std::vector<vtkActor*>& particles, bool coloured, int rawMaterial,
    vtkOpenGLRenderWindow* context);

  /**
   * New colours linear in the old ones, c' = M c for every particle: the cached tiles' bin
   * colours multiplied by M (1); 0 where the mapped colours did not change, -1 where M does not
   * exist.
   */
  int RecolourLinear(const std::vector<vtkActor*>& particles, bool coloured, int rawMaterial);

  /**
   * New colour maps of the colour coordinates where the cache keeps their moments (1); -1 where
   * a coordinate itself changed (another array, component or values, an actor now coloured
   * otherwise), the opacities changed, the ambient term of a table-coloured actor or a coloured
   * light carries the colours, or there are no moments.
   */
  int RecolourMap(const std::vector<vtkActor*>& particles, bool coloured, int rawMaterial,
    vtkOpenGLRenderWindow* context);

  /**
   * Releases the ramps' texture.
   */
  void Release(vtkWindow* w);

private:
  vtkSNDFTileCache* Cache;
  vtkSNDFColourCoordinates* Coordinates;
  // the old and the new ramp for SNDFRecolour.glsl
  vtkSmartPointer<vtkTextureObject> Ramps;
};

#endif
