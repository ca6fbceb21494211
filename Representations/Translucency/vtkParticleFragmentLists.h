/**
 * @class   vtkParticleFragmentLists
 * @brief   per-pixel lists of translucent sphere segments, composited exactly where spheres
 *          overlap
 *
 * vtkParticleFragmentLists is the exact-overlap compositing of vtkTransparentSphereMapper (its
 * EXACT_OVERLAP mode; beyond Staib et al. 2015, who name intersecting spheres as their method's
 * limitation). Instead of compositing each sphere whole in a depth order, every translucent
 * fragment appends its sphere's visible chord (start, end, impact parameter, optical-depth
 * scale, emitted colour; Shaders/Translucency/FragmentListAppend.glsl) to a linked list of its
 * pixel in shader storage (an A-buffer), and one compute pass
 * (Shaders/Translucency/FragmentListResolve.glsl) integrates each pixel's ray through the summed
 * densities: between consecutive segment boundaries the set of spheres is fixed, the optical depths
 * are the closed forms of Eq. 13-19 (EmissionAbsorption.glsl) summed, and the emitted colour is the
 * density-weighted mix of the spheres' colours (exact for constant densities, Gauss-Legendre
 * quadrature of the weights for squared-distance densities; the opacity is exact in both). Where
 * nothing overlaps the result is the sorted compositing's, and no sort is needed.
 *
 * Memory is bounded: two per-pixel arrays (heads and the second pass's pixels, 4 bytes each)
 * and a node pool of 40 bytes per fragment within MemoryBudget (MiB, default 256: 6.6 million
 * fragments, 8.3 per pixel at 1024x768). The pool grows to the count of the last overflowing
 * frame within the budget; when
 * one frame's fragments do not fit, the viewport is drawn in horizontal bands (the particles
 * drawn once per band, scissored), split in halves until each fits; a single row that does not
 * fit is composited with the fragments that did, with a warning. The resolve is two compute
 * passes holding 16 segments per pixel: the first composites every pixel whose list is no
 * longer; the second runs over the other pixels only and walks their lists in rounds, so any
 * depth is exact as long as fewer than 16 spheres overlap at one point of a ray. Where more do
 * (a band's count of such pixels is read back after the second pass), that band's long lists are
 * resolved once more by a third program holding 32 segments, built only when first needed
 * (GetLastNumberOfDeepPixels()); beyond 31 at one point the segments without room are skipped and
 * the pixels counted (GetLastNumberOfIncompletePixels(), with a warning). (Two passes are faster
 * than one carrying the rounds' code; measured: Documentation/Translucency.md.)
 *
 * Use (within vtkParticleFrontToBackTarget's Begin()/End(), with its accumulation texture):
 * Render() with a callback that draws the translucent particles with a program built from
 * GetAppendShaderCode(); the callback calls PrepareProgram() on that program once it is bound.
 *
 * Requires OpenGL 4.3 (shader storage buffers); the caller checks.
 *
 * @sa vtkTransparentSphereMapper vtkParticleFrontToBackTarget
 */
#ifndef vtkParticleFragmentLists_h
#define vtkParticleFragmentLists_h

#include "vtkObject.h"
#include "vtkParticleRenderingTranslucencyModule.h" // for export macro

#include <functional> // for std::function
#include <string>     // for std::string
#include <utility>    // for std::pair

class vtkOpenGLRenderWindow;
class vtkParticleComputeProgram;
class vtkOpenGLState;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGTRANSLUCENCY_EXPORT vtkParticleFragmentLists : public vtkObject
{
public:
  static vtkParticleFragmentLists* New();
  vtkTypeMacro(vtkParticleFragmentLists, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * GPU memory for the lists in MiB (head array and node pool), default 256, at least 1.
   */
  vtkSetClampMacro(MemoryBudget, double, 1.0, 1.0e7);
  vtkGetMacro(MemoryBudget, double);
  ///@}

  ///@{
  /**
   * The density model (vtkTransparentSphereMapper::DensityModels) and the squared hollow
   * fraction the resolve integrates with.
   */
  vtkSetMacro(DensityModel, int);
  vtkGetMacro(DensityModel, int);
  vtkSetMacro(HollowFraction2, double);
  vtkGetMacro(HollowFraction2, double);
  ///@}

  /**
   * Declarations and extension the fragment stage needs to append (insert the first string right
   * after the #version line, the second into the declarations). The append function is
   * prAppendSegment(prSegment, rayD, centerOffsetVC, maximumIntegral).
   */
  static std::string GetAppendExtension();
  static std::string GetAppendDeclarations();

  /**
   * Clear the lists, let draw() append the fragments, resolve them into `accumulation` (the
   * front-to-back accumulation, RGBA32F cleared to 0: the resolve writes each covered pixel's
   * premultiplied colour and opacity, by a compute pass); in bands if they do not fit. Its size
   * is the drawing framebuffer's (gl_FragCoord is relative to it). Returns false with an error
   * when the buffers or the resolve program cannot be made (nothing drawn then).
   */
  bool Render(vtkOpenGLRenderWindow* context, vtkTextureObject* accumulation,
    const std::function<void()>& draw);

  /**
   * Bind the lists to `program` (its storage blocks and uniforms); called by draw() after
   * binding its program.
   */
  void PrepareProgram(vtkShaderProgram* program);
  void PrepareProgram(unsigned int handle);

  ///@{
  /**
   * Statistics of the last Render(): fragments appended, bands drawn (1: the whole view at
   * once), pixels whose lists could not be composited completely, fragments left out for want of
   * memory, pixels resolved by the second pass (lists longer than 16), pixels that needed the
   * third (more than 15 spheres at one point), and bytes allocated.
   */
  vtkGetMacro(LastNumberOfFragments, long long);
  vtkGetMacro(LastNumberOfBands, int);
  vtkGetMacro(LastNumberOfIncompletePixels, long long);
  vtkGetMacro(LastNumberOfDroppedFragments, long long);
  vtkGetMacro(LastNumberOfDeferredPixels, long long);
  vtkGetMacro(LastNumberOfDeepPixels, long long);
  vtkGetMacro(AllocatedBytes, double);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkParticleFragmentLists();
  ~vtkParticleFragmentLists() override;

  double MemoryBudget = 256.0;
  int DensityModel = 0;
  double HollowFraction2 = 0.0;
  long long LastNumberOfFragments = 0;
  int LastNumberOfBands = 0;
  long long LastNumberOfIncompletePixels = 0;
  long long LastNumberOfDroppedFragments = 0;
  long long LastNumberOfDeferredPixels = 0;
  long long LastNumberOfDeepPixels = 0;
  double AllocatedBytes = 0.0;

private:
  vtkParticleFragmentLists(const vtkParticleFragmentLists&) = delete;
  void operator=(const vtkParticleFragmentLists&) = delete;

  class vtkInternals;
  vtkInternals* Internals;

  // the stages of Render(), sharing one frame's sizes and budget: the head array and the node
  // pool allocated (the pool grown, its bytes), the resolve programs built, each band's
  // fragments appended and resolved (in as many bands as the pool needs), the lists finished
  // (incomplete pixels counted, buffers unbound), the losses warned of
  struct vtkFrame;
  bool AllocateLists(vtkFrame& frame);
  bool AllocateNodes(const vtkFrame& frame, long long capacity);
  double GetAllocatedListBytes(const vtkFrame& frame);
  bool BuildResolvePrograms(vtkOpenGLRenderWindow* context);
  bool DrawBands(vtkOpenGLState* ostate, vtkTextureObject* accumulation,
    const std::function<void()>& draw, vtkFrame& frame);
  long long AppendBand(vtkOpenGLState* ostate, const std::function<void()>& draw,
    const vtkFrame& frame, const std::pair<int, int>& band);
  void ResolveBand(
    vtkTextureObject* accumulation, const vtkFrame& frame, const std::pair<int, int>& band);
  void DispatchDeferred(vtkParticleComputeProgram* program, unsigned int pixels);
  void ResolveDeepPixels(const unsigned int countersBefore[3]);
  void FinishLists();
  void WarnOfLosses();
};

#endif
