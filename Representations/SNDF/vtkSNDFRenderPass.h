/**
 * @class   vtkSNDFRenderPass
 * @brief   scale-consistent shading of sub-pixel particles: progressive screen-space normal
 *          distribution functions (S-NDFs) with re-lighting from a pre-integrated table
 *          (Ibrahim et al. 2017)
 *
 * When 10^6-10^8 particles are seen whole, each pixel covers many spheres; one ray per pixel
 * picks one normal at random and the picture aliases into noise that changes with every zoom
 * step. vtkSNDFRenderPass estimates instead, per pixel, the distribution of the normals the pixel
 * footprint sees (its S-NDF, paper Sec. 4, Eqs. 1-5) by progressive jittered sampling, and shades
 * the distribution (Sec. 5, Eqs. 12-14). The picture converges to the box-filtered super-sampled
 * image and stays consistent across zoom levels; changing the lights re-shades without sampling
 * the particles again.
 *
 * It is a vtkImageProcessingPass: its delegate renders the scene (in ParaView the Particle Render
 * View's chain, in VTK e.g. a vtkRenderStepsPass inside a vtkCameraPass).
 *
 * Distributed rendering (SetController): the sample passes' G-buffers are composited over the
 * processes by depth before they enter the S-NDFs, so every process shades the S-NDFs of the
 * whole picture, the single process's. Where the camera carries an explicit projection matrix
 * (IceT's draw callback sets one) the jitter shifts that matrix as the window centre would, and
 * a view between levels is not zoomed.
 *
 * Sampling (progressive, paper Sec. 6.3). The frame of a change (every frame of an interaction)
 * is the delegate's plain image, as fast as without the pass. While the view then holds still,
 * each Render() draws the delegate SamplesPerFrame times, each time with the camera's window centre
 * moved by a sub-pixel offset (sample k: the Halton (2, 3) point k, sample 0 at the pixel centre;
 * box filter over the pixel), into a G-buffer: the particle mappers' shaders
 * (vtkParticleSphereMapper and its opaque subclasses, through the
 * //PR::Shading::Impl hook) write the sample's view-space normal, its ambient visibility (from an
 * AO pass in the delegate) and the actor's diffuse colour into two RGBA16F targets, and into the
 * 8-bit colour target the shading that needs no normal (the occluded ambient colour and the AO
 * source's ambient light); every other shader writes zeros into the two targets (code before VTK's
 * //VTK::DepthPeeling::Impl tag), and the colour where no particle is hit (the background) is
 * kept as drawn. A compute shader enters each sample into the pixel's S-NDF: BinsPerAxis^2
 * "projected normals" bins over the unit disk (8 x 8 by default; 4 x 4 and 16 x 16 selectable),
 * 16-bit counts with the bin's mean diffuse colour and a bit mask of the occupied bins, plus the
 * pixel's sums. P_x(D_i) of Eq. 5 is a bin's count over the samples taken. Refinement stops at
 * TargetSamples per pixel (Converged).
 *
 * Shading (Eqs. 12-14). A table holds, per bin, VTK's light sums (diffuse and specular, every
 * light of the renderer as vtkParticleSphereMapper shades: the same GLSL, GetLightSumCode)
 * averaged over the normals of the bin ∩ disk, uniform in the projected (x, y): the measure that
 * uniformly hit spheres produce (the L~(D_i) of Eq. 13, pre-integrated, with sigma_perp folded in
 * because counts are already projected-area probabilities). Each pixel is then
 *
 *     L = [ sum of colours + sum_b c_b mean_b(AO*diffuse) D'(b)
 *           + specular colour * (sum AO / Nc) * sum_b c_b S'(b) ] / N
 *
 * (N samples, Nc of them on particles, the colours those of the colour target: AO*ambient plus
 * ambient light for particles, the drawn colour elsewhere; c_b the bin counts, mean_b the bin's
 * mean colour). D'(b) = D(b) + dD/du . (u_b - centroid_b), S' likewise: besides its count and
 * colour each bin keeps the mean position u_b of its samples within the bin, and the table the
 * slopes of the least-squares planes of D and S over bin ∩ disk and its centroid
 * (SNDFBins.glsl). Where a pixel's samples spread over its bins, u_b is the centroid and D' the
 * paper's D; where they crowd into part of a bin -- a particle more than a pixel wide, so that
 * each pixel sees a small patch of one sphere -- the paper's bin mean quantises the shading
 * into 8 x 8 facets, the slopes remove them, and they also lower the error of the sub-pixel
 * test crystal (measured: Documentation/SNDF.md). Re-lighting from the bins uses the
 * bin's mean colour times its mean position (colour and position within one bin taken as
 * uncorrelated). The bin sums are kept per pixel: a sample changes one bin, whose
 * contribution is taken out of the sums and put back in, computed from the stored words as a
 * re-light computes it, so a refinement frame shades in O(1) per pixel whatever the bin count.
 * The table is rebuilt whenever the lights change, and the bin sums are then formed again once
 * from the occupied bins (re-lighting: no sample is taken again).
 *
 * Choices where the paper is silent or differs (our users colour by type or speed):
 * - Colour. The paper shades normals only. Here each bin also keeps the running mean of its
 *   samples' diffuse colour (times their ambient visibility), and each pixel the sum of the
 *   ambient colours: colour and normal are correlated where about one atom covers a pixel (two
 *   species split it along their silhouettes). Per bin is more accurate than a per-pixel mean
 *   colour (measured: Documentation/SNDF.md).
 * - View vector. Normals are binned in view space; the specular term of scene lights uses
 *   VTK's view vector normalize(-p) with p on the view axis (+z), exact in the image centre and
 *   for the headlight; off-axis in a perspective view the error grows with the angle. Positional
 *   lights are evaluated at the focal distance on the view axis. Normals seen with n.z < 0
 * (possible off-axis in perspective) are binned by their (x, y) as if facing the viewer.
 * - Material. The specular colour and power are those of the first particle actor (a warning
 *   when the particle actors differ) and re-shade only. With one particle actor (ParaView's
 *   Particles representation) the samples store its colours without the property's
 *   coefficients and the shade applies them: colour by scalars -- the diffuse colour divided
 *   by the diffuse coefficient, so a new diffuse coefficient re-shades (the ambient term,
 *   ambient coefficient times the scalar colour, is drawn into the colour target and samples
 *   again when it changes); a solid colour -- white for the diffuse colour and no ambient term,
 *   so the ambient and diffuse coefficients and colours all re-shade (the ambient term is
 *   ambient coefficient * ambient colour * the pixel's sum of AO). Which of the two comes
 *   from VTK's colour code (vtkOpenGLPolyDataMapper::ReplaceShaderColor: diffuseColor =
 *   diffuseIntensity * vertex, texture or property colour), checked against the mapper's
 *   scalar settings. With more than one particle actor the samples hold the diffuse colours
 *   as drawn (coefficient times colour); an ambient change samples again, diffuse changes are
 *   colour changes (next item).
 * - Colour (the colour map, the diffuse colours). A bin keeps the mean of its samples'
 *   AO * colour, which is linear in the colours: where the particles' new stored colours are a
 *   linear function of the old ones, c' = M c for every particle of every particle actor, the
 *   bins' means become M m exactly and the pass re-shades without sampling
 *   (Shaders/SNDF/SNDFRecolour.glsl over every cached tile, then the tiles are rebaked). M is
 * fitted by least squares (pseudo-inverse) to the distinct (old, new) colour pairs of the mapped
 *   scalars (vtkMapper::MapScalars, held from the restart) and the property colours, and used
 *   only when it meets every pair within 0.05/255 with entries within +-16 (quantisation of the
 *   16-bit means: < 0.4/255). That holds for any new colours of up to three linearly
 *   independent colours -- colour by type with up to three types (LAMMPS films, binary and
 *   ternary alloys, water), a new range of such a map, solid colours of up to three actors, a
 *   diffuse coefficient (measured: Documentation/SNDF.md).
 *   Any other new map of the scalar (another preset, a new range, colour by speed, four or
 *   more types) re-shades from the bins' moments of a colour coordinate (KeepColourCoordinates,
 *   on by default), where up to four particle actors are each coloured through a lookup table
 *   or by the property's colour, at least one through a table: t in [0, 1] is each particle's
 *   value as its table sees it (the component or the magnitude) over the array's finite range
 *   (0 for a solid colour), read by particle id from a texture buffer; the sample holds
 *   t' = (a + m + (1 - 2 m) t) / K for actor a of K (m = 0.02 with several actors, 0 with one),
 *   so that each actor's colours are a part of one function of t'; each bin keeps the running means
 * of AO t^k, k = 0..3 (16 bits each, two more words per bin). A new map c' of the value moves a
 * bin's mean colour m to A Q(c') + R (m - A Q(c)): Q the two-node Gauss quadrature of the map under
 * the bin's distribution of t (from the moments: exact where a bin's samples show at most two
 * distinct values, a pixel split between two atoms; equal-weight nodes at mu -/+ sigma where the
 *   variance is below 1e-3, one node below 2.5e-5), A the bin's mean AO, R the least-squares
 *   linear map from the old map's colours to the new one's over t, which carries the old map's
 *   known quadrature error m - A Q(c) into the new one (identity for a map that is a linear
 *   function of the old one, 0 for an unrelated one). Both maps are tabulated at 4096 values of
 *   t per actor (Shaders/SNDF/SNDFRecolour.glsl); an indexed (categorical) table is tabulated with
 * the colour of the nearest value the particles have (up to 4096 distinct values), as the nodes
 * fall near the values, not on them (measured errors: Documentation/SNDF.md; two nodes do not
 * suffice for bins of three or more atoms; after a zoom out by 2 the bins and moments are averaged
 *   from the finer level, Shaders/SNDF/SNDFDownsample.glsl). Still sampling again:
 *   NaN or Inf values (the table's NaN and out-of-range colours are not functions of t), more
 *   particles than a texture buffer holds, more than four particle actors or direct colours, a
 *   scalar actor with an ambient coefficient (the ambient term is drawn with the scalar
 *   colours into the colour target, which keeps no bins), a voxel-cone ambient light (it
 *   carries the particles' colours), new opacities, another array or component, new scalars or
 *   new geometry.
 * - Memory. An S-NDF texel takes 12 BinsPerAxis^2 + 4 max(1, BinsPerAxis^2 / 32) + 64 bytes (a
 *   16-bit count, three 16-bit mean colour channels and two 16-bit mean bin coordinates per
 *   bin, the occupancy bits, four float sums; 8 x 8 bins: 840 bytes, 3.3 MB per 64^2 tile), and
 *   8 BinsPerAxis^2 bytes more with the colour coordinates' moments (8 x 8 bins: 1352 bytes,
 *   5.3 MB per tile; dropped with a warning where MaximumMemory does not hold them). The
 *   S-MIP cache (below) takes MaximumMemory MB (MiB; default 1536), at most eight views' worth
 *   of tiles; a view needs up to (ceil(W / 64) + 1) (ceil(H / 64) + 1) tiles (273 at 1280 x 720:
 *   896 MB with 8 x 8 bins). Where MaximumMemory
 *   does not hold the view's tiles the pass uses fewer bins, and renders the plain delegate when
 *   even 4 x 4 do not fit, with a warning each time ("cache too small": never a wrong tile).
 *   The cache is split into shader-storage buffers of whole tiles within the context's
 *   GL_MAX_SHADER_STORAGE_BLOCK_SIZE (llvmpipe: 128 MB, 42 tiles of 8 x 8 bins per buffer; at
 *   most 64 buffers), see vtkSNDFTileCache.
 *
 * S-MIP (paper Sec. 6, vtkSNDFTileCache). The S-NDFs are texels of a virtual image plane parallel
 * to the screen, fixed at the restart: level 0 has the restart view's pixels as texels, level L
 * texels 2^L times as large. They are kept in 64^2 tiles in a fixed pool of GPU memory with a
 * page table and least-recently-used replacement. In parallel projection, a view whose pixels
 * are texels of a level -- parallel scale 2^L times that of the restart (-8 <= L <= 24), the
 * camera moved in the view plane only -- keeps the samples:
 * - a pan (Sec. 6.1.3, 6.2.1) shows the tiles in the cache at once (converged where they were)
 *   and samples only the texels the cache does not have (texels holding TargetSamples take no
 *   more); a pan back finds the old tiles while the cache holds them. A pan by a whole number
 *   of pixels stays on the level's grid; other pans use a grid of another phase (placed to
 *   1/256 pixel: the texels lie within 1/512 pixel of the view's pixels), whose tiles are new
 *   unless that grid was seen before;
 * - a zoom out by 2 or 4 (parallel scale times 2 or 4) averages the coarser level from the
 *   finer one in the cache (Sec. 6.1.2: 2 x 2 or 4 x 4 normalised S-NDFs per texel, a box
 *   filter); where the finer level was sampled no sample is taken; a zoom back in shows the
 *   cached finer level;
 * - a view none of whose tiles the cache has or can average is the frame of a change: the
 *   plain image, sampling from the next frame on (unless ConvergeOnRender).
 * Other zoom factors restart by default; with ZoomBetweenLevels on they keep the samples (the
 * paper displays such views "by interpolating between two adjacent S-MIP levels, as in standard
 * tri-linear mipmap filtering"). Here the view is placed at the finer of its two levels (its
 * pixels 1 to 2 texels wide, on that level's phase-0 grid), the texels of a rectangle around the
 * window are sampled where the cache lacks them (each sample pass renders the rectangle, up to
 * 2x the window per axis, with a camera whose pixels are those texels), shaded, and each window
 * pixel is the box filter of the texels under its footprint, weighted by the area they share
 * (Shaders/SNDF/SNDFBoxFilter.glsl): shading is linear in the S-NDF, so this is the shade of the
 * footprint's averaged S-NDF -- sharper than the trilinear tent filter, and consistent under
 * pans. It is still the zoomed picture convolved with a texel's box, and the blur is the
 * method's (measured: Documentation/SNDF.md). Hence off by default. A rectangle whose tiles exceed
 * the cache restarts. Rotations and perspective camera moves restart (the paper's S-MIP, too, is
 * invalidated by a new view direction).
 *
 * What invalidates the samples: the viewport size, the camera (but for the pans and zooms
 * above: view up, view direction, view angle, projection, clipping range, window centre, in
 * perspective also position, focal point), the bins, the cache size, and any
 * prop's or mapper's (a particle mapper's without its lookup table) or input's modification
 * time (props outside the view count too: panning
 * them out of the view and back keeps the S-MIP), the background, the passes inside this one
 * (their objects and modification times: an AO pass put into the chain or changed). What does
 * not: lights (the table is rebuilt when a light's colour or its direction or position in view
 * coordinates changes; each cached tile is rebaked when it is next shown or averaged), the
 * particle actors' specular colour and power, and colour changes linear in the colours
 * ("Colour" above).
 *
 * Other geometry. Opaque polygonal props (surfaces, lines, points: any vtkActor whose mapper takes
 * render-pass shader replacements) are sampled with the particles: their colour goes into the
 * colour target as drawn and their fragments overwrite the particle targets with "no particle"
 * (alpha 1, since VTK blends opaque geometry too), so a box through a crystal or the simulation
 * box's outline converge to the super-sampled image like the particles (lines are box-filtered:
 * anti-aliased). Particle samples are told from the background by their ambient visibility
 * stored plus 2: a delegate that clears its target (vtkRenderStepsPass does) fills the particle
 * targets with the background colour, components in [0, 1].
 *
 * Unsupported scenes fall back to the delegate's plain image with one warning: translucent
 * actors (particles or other geometry: what lies behind them would have to be attenuated),
 * props that are not actors (volumes, images, 2D actors), vtkMetaballMapper (it draws through
 * its own targets), contexts without OpenGL 4.3 compute shaders, a vtkPointAOPass inside this pass
 * (screen-space occlusion darkens the composited image; the samples need it per fragment).
 * A renderer whose viewport does not fill its window (renderers side by side in plain VTK) is
 * rendered plainly too (the delegate's camera pass sets up the window's viewport).
 * vtkTransparentSphereMapper (ParaView's Particles representation) is sampled while all its
 * particles are opaque: it then draws them through the core's opaque path. The background, plain or
 * gradient, is sampled with the particles. Without particle props the pass renders the delegate
 * directly.
 *
 * @sa vtkParticleSphereMapper vtkParticleShaderHooks vtkImageProcessingPass
 */
#ifndef vtkSNDFRenderPass_h
#define vtkSNDFRenderPass_h

#include "vtkImageProcessingPass.h"
#include "vtkParticleRenderingSNDFModule.h" // for export macro

#include <vector> // for std::vector

class vtkFloatArray;
class vtkMultiProcessController;
class vtkSNDFTileCache;

class VTKPARTICLERENDERINGSNDF_EXPORT vtkSNDFRenderPass : public vtkImageProcessingPass
{
public:
  static vtkSNDFRenderPass* New();
  vtkTypeMacro(vtkSNDFRenderPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  ///@{
  /**
   * Jittered samples per pixel added by each Render() while the view holds still (default 4;
   * the Render() of a change shows the plain image and takes none).
   */
  vtkSetClampMacro(SamplesPerFrame, int, 1, 4096);
  vtkGetMacro(SamplesPerFrame, int);
  ///@}

  ///@{
  /**
   * When on, every Render() takes the samples still missing to TargetSamples, also on the frame
   * of a change (off by default: the frame of a change is the plain image and each Render() adds
   * SamplesPerFrame). For batch rendering and screenshots: one Render() gives the converged
   * image. In ParaView the Particle Render View switches it on for still renders with
   * "Converge Still Renders" (pvpython, pvbatch, Save Screenshot).
   */
  vtkSetMacro(ConvergeOnRender, bool);
  vtkGetMacro(ConvergeOnRender, bool);
  vtkBooleanMacro(ConvergeOnRender, bool);
  ///@}

  ///@{
  /**
   * Distributed rendering: the processes whose pictures are composited by depth into one (e.g.
   * IceT under ParaView's pvbatch or pvserver; nullptr or one process, the default: this process
   * draws the whole picture). With more than one, every sample pass's G-buffer is composited
   * over the processes before it enters the S-NDFs -- per pixel the nearest fragment of any
   * process, with the normal, colour and diffuse values its process wrote
   * (vtkParticleGBufferExchange) -- so every process gathers, shades and composites the S-NDFs
   * of the whole picture, the single process's. Collective: every process renders every frame
   * and the decisions that change what is sampled (restart, the frame of a change, sampling at
   * all) are taken together; a process without particles in view takes part with an empty
   * G-buffer. In ParaView the Particle Render View sets it.
   */
  void SetController(vtkMultiProcessController* controller);
  vtkMultiProcessController* GetController();
  ///@}

  ///@{
  /**
   * Parallel zooms by factors other than powers of two (ParaView's mouse wheel) keep the
   * samples when on: the view is placed at the nearest S-MIP level and shown as the box filter
   * of that level's texels (class description, "S-MIP"), at once where the level was sampled,
   * sampling only texels the cache lacks. The picture is then blurred by up to a texel and does
   * not refine beyond it (measured: Documentation/SNDF.md). Off (default): such a zoom
   * samples anew at the view's pixels.
   */
  vtkSetMacro(ZoomBetweenLevels, bool);
  vtkGetMacro(ZoomBetweenLevels, bool);
  vtkBooleanMacro(ZoomBetweenLevels, bool);
  ///@}

  ///@{
  /**
   * With up to four particle actors coloured through lookup tables (colour by speed, by type,
   * ...) or by their property's colour, keep each bin's moments of the particles' scalar (class
   * description, "Colour"), so that any new colour map of that scalar -- another preset, a new
   * range, continuous or not -- re-shades without sampling. On by default; costs two 32-bit words
   * per bin (8 x 8 bins: 512 more bytes per texel, 1352 instead of 840; accumulation time measured:
   * Documentation/SNDF.md).
   * Off: only colour maps whose new colours are linear in the old ones re-shade.
   */
  vtkSetMacro(KeepColourCoordinates, bool);
  vtkGetMacro(KeepColourCoordinates, bool);
  vtkBooleanMacro(KeepColourCoordinates, bool);
  ///@}

  ///@{
  /**
   * Samples per pixel at which refinement stops (default 256, at most 65535: 16-bit bin counts).
   */
  vtkSetClampMacro(TargetSamples, int, 1, 65535);
  vtkGetMacro(TargetSamples, int);
  ///@}

  ///@{
  /**
   * S-NDF bins per axis of the projected-normal square: 4, 8 (default) or 16. Other values are
   * refused with an error.
   */
  void SetBinsPerAxis(int bins);
  vtkGetMacro(BinsPerAxis, int);
  ///@}

  ///@{
  /**
   * The size of the S-MIP cache in MB (MiB; default 1536, 1.7 views of 1280 x 720 with 8 x 8
   * bins; it takes at most eight views' worth of tiles). See the class description for a view whose
   * tiles do not fit.
   */
  vtkSetClampMacro(MaximumMemory, double, 0.0, 1.0e7);
  vtkGetMacro(MaximumMemory, double);
  ///@}

  /**
   * The fewest samples any pixel of the current view holds, at most TargetSamples (0 before the
   * first render or after a change; TargetSamples when no particle is in the view).
   */
  vtkGetMacro(NumberOfSamples, int);

  ///@{
  /**
   * Stop refinement early once the estimated mean error of the picture falls to ErrorTarget (in
   * 1/255 of the colour range, over the view's pixels and channels; default 0: off, refinement
   * goes on to TargetSamples). The estimate compares the picture after N samples with the one
   * after M <= N / 2 (checked at N = 2, 4, 8, ... as the samples arrive): mean |I_N - I_M| *
   * sqrt(M / (N - M)), the mean error of I_N for independent samples (for the jittered
   * low-discrepancy samples here it errs on the safe side). It measures the sampling noise, not
   * the binning's error (what 256 samples leave: TestSNDFRenderPass). GetEstimatedError() is the
   * last estimate (-1 before the first). A change of the view starts again.
   */
  vtkSetClampMacro(ErrorTarget, double, 0.0, 255.0);
  vtkGetMacro(ErrorTarget, double);
  vtkGetMacro(EstimatedError, double);
  ///@}

  /**
   * True when refinement stopped: NumberOfSamples reached TargetSamples, or the estimated error
   * reached ErrorTarget.
   */
  bool GetConverged()
  {
    return this->NumberOfSamples >= this->TargetSamples || this->ErrorTargetReached;
  }

  /**
   * The bins per axis in use (BinsPerAxis, or fewer when MaximumMemory forced it; 0 when the pass
   * renders the plain delegate).
   */
  vtkGetMacro(ActiveBinsPerAxis, int);

  /**
   * Bytes of GPU memory the S-MIP cache takes now.
   */
  vtkGetMacro(MemoryBytes, double);

  ///@{
  /**
   * Counters for tests and benchmarks: delegate renders into the G-buffer (sample passes), S-NDF
   * restarts, lighting-table builds, re-shades, pans and zooms that kept the S-MIP, colour-map
   * changes that recoloured the samples since the pass was created.
   */
  vtkGetMacro(NumberOfSamplePasses, vtkIdType);
  vtkGetMacro(NumberOfRestarts, vtkIdType);
  vtkGetMacro(NumberOfTableBuilds, vtkIdType);
  vtkGetMacro(NumberOfResolves, vtkIdType);
  vtkGetMacro(NumberOfPans, vtkIdType);
  vtkGetMacro(NumberOfZooms, vtkIdType);
  vtkGetMacro(NumberOfRecolours, vtkIdType);
  ///@}

  /**
   * The S-MIP cache (its tiles, slots and counters; owned by the pass).
   */
  vtkSNDFTileCache* GetTileCache();

  /**
   * A Render() that takes 8 sample passes or more (ConvergeOnRender, a large SamplesPerFrame)
   * reports its progress as a vtkAlgorithm does: vtkCommand::ProgressEvent on this pass with the
   * fraction of its sample passes done (a double) as call data, from 0 to 1, while
   * GetProgressText() names the work (ParaView's Particle Render View forwards both to its
   * progress bar).
   */
  const char* GetProgressText();

  /**
   * Forget the samples: the next Render() starts again.
   */
  void Restart();

  ///@{
  /**
   * Per-stage GPU times of the last Render() in seconds, from timer queries, with CollectTimings
   * on (off by default; reading them waits for the GPU): the sample passes (delegate draws into the
   * G-buffer), their accumulation into the S-NDFs, the lighting table, the re-shade and the final
   * composite.
   */
  vtkSetMacro(CollectTimings, bool);
  vtkGetMacro(CollectTimings, bool);
  vtkBooleanMacro(CollectTimings, bool);
  double GetLastSampleSeconds();
  double GetLastAccumulateSeconds();
  double GetLastShadeSeconds();
  ///@}

  /**
   * The lighting table of the last Render() (needs the render window's context current): 2 *
   * bins^2 tuples of 3 components, the diffuse light sums of bins 0 .. bins^2 - 1, then the
   * specular ones (bin (i, j) is number j * bins + i over x, y in [-1, 1]). False before a
   * table was built.
   */
  bool GetLightingTable(vtkFloatArray* table);

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;

protected:
  vtkSNDFRenderPass();
  ~vtkSNDFRenderPass() override;

  int SamplesPerFrame = 4;
  int TargetSamples = 256;
  int BinsPerAxis = 8;
  double MaximumMemory = 1536.0;
  bool KeepColourCoordinates = true;
  int NumberOfSamples = 0;
  int ActiveBinsPerAxis = 0;
  double MemoryBytes = 0.0;
  vtkIdType NumberOfSamplePasses = 0;
  vtkIdType NumberOfRestarts = 0;
  vtkIdType NumberOfTableBuilds = 0;
  vtkIdType NumberOfResolves = 0;
  vtkIdType NumberOfPans = 0;
  vtkIdType NumberOfZooms = 0;
  vtkIdType NumberOfRecolours = 0;
  bool CollectTimings = false;
  bool ConvergeOnRender = false;
  bool ZoomBetweenLevels = false;
  double ErrorTarget = 0.0;
  double EstimatedError = -1.0;
  bool ErrorTargetReached = false;

private:
  vtkSNDFRenderPass(const vtkSNDFRenderPass&) = delete;
  void operator=(const vtkSNDFRenderPass&) = delete;

  ///@{
  /**
   * The stages of Render(), in order (each one that returns bool returns false when it has
   * drawn the frame itself, without S-NDFs), and the shade and error estimate they share.
   */
  struct vtkFrame;
  void RenderPlain(const vtkRenderState* s);
  void CollectScene(vtkFrame& frame);
  bool CheckSupport(vtkFrame& frame);
  void RenderWithoutParticles(vtkFrame& frame);
  bool ChooseBins(vtkFrame& frame);
  void DescribeView(vtkFrame& frame);
  void PrepareContext(vtkFrame& frame);
  bool KeepOrRestartSamples(vtkFrame& frame);
  bool ShowChangeFrame(vtkFrame& frame);
  bool PrepareTargets(vtkFrame& frame);
  void ChooseMaterial(vtkFrame& frame);
  std::vector<double> LightingTableKey(vtkFrame& frame);
  bool UpdateLightingTable(vtkFrame& frame);
  bool MapTiles(vtkFrame& frame);
  void TakeSamples(vtkFrame& frame);
  void RenderSampleTargets(vtkFrame& frame);
  void AccumulateSamples(vtkFrame& frame);
  void ResolveView(vtkFrame& frame);
  void CheckError(vtkFrame& frame);
  void Shade(vtkFrame& frame);
  void Composite(vtkFrame& frame);
  ///@}

  ///@{
  /**
   * Distributed rendering (SetController): AllProcesses is the logical AND of `local` over the
   * processes (`local` with one process); AgreeToSample draws the plain frame on a process that
   * was ready when another was not, and returns whether all were; ExchangeSampleTargets
   * composites the sample pass's G-buffer over the processes by depth. Collective.
   */
  bool AllProcesses(bool local);
  bool AgreeToSample(bool local, vtkFrame& frame);
  void ExchangeSampleTargets(vtkFrame& frame);
  ///@}

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
