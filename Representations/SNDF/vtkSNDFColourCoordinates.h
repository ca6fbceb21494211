/**
 * @class   vtkSNDFColourCoordinates
 * @brief   the colour coordinates of vtkSNDFRenderPass's particle actors and their ramp
 *
 * vtkSNDFRenderPass's class description, "Colour" (KeepColourCoordinates): for up to
 * MaximumActors particle actors, each coloured through a lookup table or by its property's
 * colour (at least one through a table; CanKeep()), each particle's value as the table sees it
 * (one component or the magnitude) is kept as t in [0, 1] over the array's finite range, in a
 * float texture buffer the sample pass reads by particle id. The sample holds
 * t' = (a + Margin + (1 - 2 Margin) t) / K for actor a of K (Place(); a solid actor t = 0), so
 * that the cache's bins keep moments of t' and a new colour map re-shades from them
 * (Shaders/SNDF/SNDFRecolour.glsl). Ramp is the stored colour as a function of t' (RampPerActor
 * RGBA entries per actor, MakeRamp()) for the maps the samples hold; an indexed (categorical) table
 * maps each t' to the colour of the nearest value the particles have (NearestCategory()).
 *
 * The arithmetic (Normalise(), Place(), NearestCategory(), MakeRamp()) needs no OpenGL;
 * Update() uploads the coordinates, Source() hands them to the sample pass. Plain C++ (no
 * vtkObject); vtkSNDFRenderPass holds one, vtkSNDFRecolouring reads it.
 * TestSNDFColourCoordinates checks the arithmetic alone.
 *
 * @sa vtkSNDFRenderPass vtkSNDFRecolouring vtkSNDFTileCache
 */
#ifndef vtkSNDFColourCoordinates_h
#define vtkSNDFColourCoordinates_h

#include "vtkParticleRenderingSNDFModule.h" // for export macro
#include "vtkSmartPointer.h"                // for vtkSmartPointer
#include "vtkType.h"                        // for vtkIdType, vtkMTimeType
#include "vtkWeakPointer.h"                 // for vtkWeakPointer

#include <functional> // for std::function
#include <string>     // for std::string
#include <vector>     // for std::vector

class vtkActor;
class vtkDataArray;
class vtkMapper;
class vtkOpenGLBufferObject;
class vtkOpenGLRenderWindow;
class vtkObject;
class vtkProp;
class vtkScalarsToColors;
class vtkTextureObject;
class vtkUnsignedCharArray;
class vtkWindow;

class VTKPARTICLERENDERINGSNDF_EXPORT vtkSNDFColourCoordinates
{
public:
  static constexpr int RampPerActor = 4096;
  static constexpr int MaximumActors = 4;

  /**
   * What the diffuse colour of an actor's samples is: Scale * the mapped scalar colours
   * (Colours, modified at Time; Scale the diffuse coefficient, or 1 where the shade applies
   * it), or Solid where there are no scalars.
   */
  struct SampledColours
  {
    vtkSmartPointer<vtkUnsignedCharArray> Colours;
    vtkMTimeType Time = 0;
    double Scale = 1.0;
    double Solid[3] = { 0.0, 0.0, 0.0 };
  };

  /**
   * One actor's coordinates: its array, component (-1: the magnitude) and the array's
   * modification time when computed, the finite range t spans, the distinct values (found when
   * an indexed table first needs them, empty beyond 4096) and the uploaded texture buffer.
   */
  struct Actor
  {
    bool Valid = false;
    bool Solid = false; // the property's colour: no texture, t = 0
    vtkWeakPointer<vtkDataArray> Array;
    vtkMTimeType Time = 0;
    int Component = 0;
    double Range[2] = { 0.0, 0.0 };
    bool HaveCategories = false;
    std::vector<double> Categories;
    vtkSmartPointer<vtkOpenGLBufferObject> Buffer;
    vtkSmartPointer<vtkTextureObject> Texture;
  };

  std::vector<Actor> Actors;
  std::vector<vtkProp*> Props;
  std::vector<float> Ramp;
  // a one-value buffer texture that solid actors' draws read
  vtkSmartPointer<vtkOpenGLBufferObject> SolidBuffer;
  vtkSmartPointer<vtkTextureObject> SolidTexture;
  // whether the sample shader writes the coordinates (the shader variant with them)
  bool InShader = false;

  ///@{
  /**
   * The margin between the actors' intervals of t' (0.02 for more than one actor) and where
   * actor `a` of `count` places t: t' = offset + scale t.
   */
  double Margin() const { return Margin(this->Actors.size()); }
  static double Margin(std::size_t count) { return count > 1 ? 0.02 : 0.0; }
  static void Place(std::size_t a, std::size_t count, float& offset, float& scale);
  ///@}

  /**
   * Whether the mapper colours by scalars (as vtkMapper::MapScalars decides): its shader's
   * diffuse and ambient colours are then the scalars'; an input that is not a data set counts
   * as coloured by scalars.
   */
  static bool UsesScalarColours(vtkMapper* mapper);

  /**
   * The colours the samples of a particle actor hold, as far as a colour map makes them: its
   * mapper's mapped scalars, null for the property's colour.
   */
  static vtkUnsignedCharArray* MappedColours(vtkActor* actor);

  /**
   * Where a particle actor's colours come from a lookup table of one value per particle: the
   * point array, the table and the component it maps (-1: the magnitude). False for direct
   * colours, cell scalars and the RGB vector mode.
   */
  static bool FindSource(
    vtkActor* actor, vtkDataArray*& array, vtkScalarsToColors*& table, int& component);

  /**
   * Whether the particle actors can keep colour coordinates: 1 to MaximumActors actors, each
   * coloured through a lookup table (FindSource()) or by its property's colour, at least one
   * through a table.
   */
  static bool CanKeep(const std::vector<vtkActor*>& particles);

  /**
   * Particle i's value of `array` as the table sees it: `component`, or the magnitude (-1).
   * `tuple` holds the array's number of components.
   */
  static double Value(vtkDataArray* array, vtkIdType i, int component, double* tuple);

  /**
   * Each particle's t in [0, 1] over the values' range (0 where the range is one value) and
   * that range; false where a value is not finite.
   */
  static bool Normalise(vtkDataArray* array, int component, double range[2], std::vector<float>& t);

  /**
   * The distinct values of an actor's coordinate array (at most 4096; false beyond).
   */
  static bool FindCategories(Actor& c);

  /**
   * The value of sorted, non-empty `categories` nearest to v (the greater one at a tie).
   */
  static double NearestCategory(const std::vector<double>& categories, double v);

  /**
   * The coordinates of the particle actors up to date (an actor's computed again only when its
   * array, the array's modification time or the component changed); false where they cannot be
   * kept: non-finite values (the table's NaN and out-of-range colours are not a function of the
   * clamped value), more particles than a texture buffer holds (reported once through
   * `firstWarning` to `owner`). For actors that pass CanKeep().
   */
  bool Update(const std::vector<vtkActor*>& particles, vtkOpenGLRenderWindow* context,
    vtkObject* owner, const std::function<bool(const std::string&)>& firstWarning);

  /**
   * Where the sample pass reads the coordinate of `prop`'s particles and how it places it in
   * [0, 1] (t' = offset + scale t); null where `prop` keeps none.
   */
  vtkTextureObject* Source(vtkProp* prop, float& offset, float& scale, int& solid) const;

  /**
   * The stored colours (`stored`: the scale times the table's colour, or the solid colour) at
   * RampPerActor values of t per actor (the whole [0, 1] of t'), through `tables` (one per
   * actor, null for a solid actor) as they map now; alpha the table's (1 for a solid colour).
   * Empty where an indexed table meets more than 4096 distinct values or the sizes disagree.
   */
  std::vector<float> MakeRamp(
    const std::vector<vtkScalarsToColors*>& tables, const std::vector<SampledColours>& stored);

  /**
   * MakeRamp() through the particle actors' lookup tables.
   */
  std::vector<float> MakeRamp(
    const std::vector<vtkActor*>& particles, const std::vector<SampledColours>& stored);

  /**
   * The textures left inactive after the sample pass.
   */
  void Deactivate();

  /**
   * Releases the textures and forgets the coordinates and the ramp (uploaded again when next
   * needed).
   */
  void Release(vtkWindow* w);

private:
  bool UpdateActor(Actor& c, vtkActor* actor, vtkOpenGLRenderWindow* context, vtkObject* owner,
    const std::function<bool(const std::string&)>& firstWarning);
};

#endif
