/**
 * @class   vtkMetaballWalkingPlane
 * @brief   the buffers and the loop of the "walking depth plane" metaball method
 *          (Mueller, Grottel, Ertl 2007, Sec. 3.2)
 *
 * vtkMetaballWalkingPlane holds, for one view, the per-pixel state of the walking depth plane
 * and advances it; vtkMetaballMapper draws its particles into it (the splat passes) and shades
 * the result (its final draw). Per pixel, in RGBA32F textures the size of the viewport:
 *
 * - the plane ("lambda buffer", Sec. 3.2.1): (lambda, -lambda_max, finished, 0). lambda is the
 *   view depth of the plane's point on the pixel's ray, measured from the depth of the
 *   particles' vertex-buffer origin (so that it keeps float precision with the camera far away
 *   or the data far from the origin); lambda_max the deepest back side of an influence sphere on
 *   the ray. StartInitialization() clears it to +inf and selects MIN blending: the mapper draws
 *   the influence spheres writing (front, -back) (the paper's two depth-tested passes in one).
 * - the density (Sec. 3.2.2): (D(lambda), dD/dlambda, D(lambda + MaximumStep), n), summed
 *   over the particles by additive blending; n counts the particles that saw the pixel active
 *   (not finished and lambda <= lambda_max). The derivative and the sample ahead are the
 *   paper's "evaluating the density field at multiple depths at one time", used by the oracle.
 * - the shading buffers (Sec. 3.2.5): the field's gradient and value at lambda, and the
 *   particles' colours summed with their kernel values as weights.
 *
 * Step() moves the plane (Sec. 3.2.3) by a full-viewport pass that reads only the density and
 * adds the step to the plane by blending (no texture is read and written by one pass), then
 * closes the finished and exhausted pixels in a depth mask shared with the density buffer (the
 * paper's shared depth attachment: the density draws, at depth 0.5 with GL_LESS and without
 * depth writes, skip them before the fragment stage):
 * a pixel is finished when Newton's estimate of its distance to the surface, |t - D| / D',
 * is at most DepthTolerance (D' = dD/dlambda > 0), or, where the field does not rise with
 * depth (a ray touching the surface), when |D/t - 1| <= DensityTolerance. D > t steps back
 * MaximumStep (D/t - 1) / 2 (the paper's linear attenuation); D < t steps forward:
 * - PAPER_ORACLE: MaximumStep (1 - (D/t)^2), the paper's quadratic attenuation;
 * - BRACKETING_ORACLE (default): Newton's step (t - D) / D' where the field rises with depth,
 *   kept within one MaximumStep; else the secant to the sample ahead when that reaches t, else
 *   the full MaximumStep (a surface thinner than the step along the ray can be missed, as with
 *   the paper's oracle, Sec. 3.2.3). Behind the surface where the field falls with depth (past
 *   a maximum) half a MaximumStep back. It converges in far fewer passes (the droplet of
 *   TestMetaballWalkingPlane: 41 against 122).
 *
 * Termination (Sec. 3.2.4), whichever comes first: no active pixel left; the share of finished
 * pixels among the covered ones reaches FinishedShare (the paper could not count them: an
 * occlusion query on the step pass counts the active pixels; it is read before the next pass);
 * a stall: at most 1 % of the covered pixels (and at least one) still active and their number
 * unchanged for StallPasses passes (default 32; pixels whose step oscillates about a surface the
 * ray grazes, which the step rule never finishes: the bundled droplets leave 1 to 78 of about
 * 85 000 in most still frames of TestMetaballsParaView); MaximumPasses; TimeBudget seconds since
 * the start of the frame's walk (the paper's minimum frame rate). GetTermination() says which.
 *
 * Between Begin() and End() the OpenGL state is the walk's (own framebuffers, viewport at the
 * origin, no depth test); End() restores it exactly. The textures stay valid for the final draw.
 *
 * @sa vtkMetaballMapper
 */
#ifndef vtkMetaballWalkingPlane_h
#define vtkMetaballWalkingPlane_h

#include "vtkObject.h"
#include "vtkParticleRenderingMetaballsModule.h" // for export macro

class vtkRenderer;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGMETABALLS_EXPORT vtkMetaballWalkingPlane : public vtkObject
{
public:
  static vtkMetaballWalkingPlane* New();
  vtkTypeMacro(vtkMetaballWalkingPlane, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Oracle
  {
    PAPER_ORACLE = 0,
    BRACKETING_ORACLE = 1
  };
  enum Termination
  {
    NOT_RUN = 0,
    CONVERGED = 1,      // no active pixel left
    FINISHED_SHARE = 2, // the finished share reached FinishedShare
    PASS_LIMIT = 3,     // MaximumPasses
    TIME_BUDGET = 4,    // TimeBudget
    STALLED = 5         // a few active pixels that stopped finishing (StallPasses)
  };

  ///@{
  /**
   * The walk's settings (vtkMetaballMapper sets them from its own): the iso-value t, the
   * largest step (view units), the tolerance on D / t, the oracle, the limits.
   */
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  vtkSetMacro(MaximumStep, double);
  vtkGetMacro(MaximumStep, double);
  vtkSetMacro(DepthTolerance, double);
  vtkGetMacro(DepthTolerance, double);
  vtkSetMacro(DensityTolerance, double);
  vtkGetMacro(DensityTolerance, double);
  vtkSetMacro(StepOracle, int);
  vtkGetMacro(StepOracle, int);
  vtkSetMacro(MaximumPasses, int);
  vtkGetMacro(MaximumPasses, int);
  vtkSetMacro(TimeBudget, double);
  vtkGetMacro(TimeBudget, double);
  vtkSetMacro(FinishedShare, double);
  vtkGetMacro(FinishedShare, double);
  vtkSetMacro(StallPasses, int);
  vtkGetMacro(StallPasses, int);
  ///@}

  /**
   * Start a walk in the renderer's current viewport: (re)allocate the buffers, save the OpenGL
   * state. False (with an error) when the buffers cannot be made.
   */
  bool Begin(vtkRenderer* ren);

  /**
   * The viewport the walk covers, in the framebuffer that was bound at Begin(): x, y, w, h.
   */
  const int* GetViewport() const { return this->Viewport; }

  /**
   * Bind the plane for the initialisation draw (cleared to +inf, MIN blending).
   */
  void StartInitialization();

  /**
   * Whether the walk goes on (see Termination); if so, bind the density buffer (cleared to 0,
   * additive blending) for the next density draw.
   */
  bool StartDensity();

  /**
   * Move the plane by the density just drawn.
   */
  void Step();

  /**
   * Bind the gradient buffer (color false) or the colour buffer (color true), cleared to 0 with
   * additive blending, for a shading draw.
   */
  void StartShading(bool color);

  /**
   * Restore the OpenGL state of Begin().
   */
  void End();

  ///@{
  /**
   * The textures (valid after End() until the next Begin()).
   */
  vtkTextureObject* GetPlaneTexture();
  vtkTextureObject* GetGradientTexture();
  vtkTextureObject* GetColorTexture();
  ///@}

  ///@{
  /**
   * The last walk: density passes, seconds (CPU wall clock, the occlusion queries synchronise
   * it with the GPU), pixels covered by an influence sphere, pixels still active when it
   * stopped (measured at the last counted pass), why it stopped.
   */
  vtkGetMacro(NumberOfPasses, int);
  vtkGetMacro(Seconds, double);
  vtkGetMacro(CoveredPixels, long long);
  vtkGetMacro(ActivePixels, long long);
  vtkGetMacro(Termination, int);
  ///@}
  static const char* GetTerminationAsString(int termination);

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkMetaballWalkingPlane();
  ~vtkMetaballWalkingPlane() override;

  double IsoValue = 1.0;
  double MaximumStep = 1.0;
  double DepthTolerance = 1e-3;
  double DensityTolerance = 1e-3;
  int StepOracle = BRACKETING_ORACLE;
  int MaximumPasses = 100;
  double TimeBudget = 1.0;
  double FinishedShare = 1.0;
  int StallPasses = 32;

  int Viewport[4] = { 0, 0, 0, 0 };
  int NumberOfPasses = 0;
  double Seconds = 0.0;
  long long CoveredPixels = 0;
  long long ActivePixels = 0;
  int Termination = NOT_RUN;

private:
  vtkMetaballWalkingPlane(const vtkMetaballWalkingPlane&) = delete;
  void operator=(const vtkMetaballWalkingPlane&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
