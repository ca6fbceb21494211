/**
 * @class   vtkParticleRenderView
 * @brief   ParaView's Render View with the particle pass frame
 *
 * vtkParticleRenderView is the view through which ParticleRendering's render passes (ambient
 * occlusion and the techniques after it) reach ParaView. It is registered in the server-manager
 * XML as "ParticleRenderView" ("Particle Render View") with the Render View as its base proxy,
 * so it has every property of the standard Render View. It is otherwise a plain
 * vtkPVRenderView: it renders every representation (not only Particles) and, while its pass
 * chain is empty, produces exactly the images of the standard Render View (TestParticleRenderView
 * compares the two).
 *
 * Why a view subclass. A pass set with vtkRenderer::SetPass() does not survive in ParaView:
 * vtkPVSynchronizedRenderer::SetupPasses() rebuilds the renderer's pass chain
 *
 *     [vtkOpenGLFXAAPass] -> [ImageProcessingPass] -> vtkCameraPass -> (RenderPass |
 * vtkPVDefaultPass)
 *
 * whenever FXAA, the image-processing pass (EDL, tone mapping), the renderer or the parallel
 * configuration change (with IceT it hands the same two slots to vtkIceTSynchronizedRenderers).
 * The two slots are kept as members of vtkPVSynchronizedRenderer and reused by every rebuild,
 * but they can be set only through vtkPVRenderView::SynchronizedRenderers, which is protected.
 * This class therefore installs its vtkParticlePassChain once, in the constructor, in the
 * render-pass slot (`SynchronizedRenderers->SetRenderPass(chain)`), like vtkPVRenderViewWithEDL
 * installs its pass in the image-processing slot. Later rebuilds keep it.
 *
 * Who else uses the slot. Only two ParaView features replace the render pass, and both restore
 * the saved one afterwards: ray tracing (EnableOSPRay; the chain is not used while OSPRay or
 * OptiX render) and value passes (BeginValuePassForRendering / EndValuePassForRendering, used for
 * value capture). As a safeguard the view re-installs the chain before a local render if it
 * finds the slot empty; it never replaces another pass put there on purpose.
 *
 * Why the render-pass slot and not the image-processing slot. The image-processing slot is
 * shared with EDL and tone mapping and sits outside the camera pass; the render-pass slot sits
 * inside the camera pass (the camera is set up when the chain runs, as particle passes need) and
 * its pass replaces vtkPVDefaultPass, which the chain therefore keeps as its innermost delegate,
 * so lights, translucency (depth peeling), volumes, overlays and the renderer's own SSAO ("Use
 * Ambient Occlusion") behave as in the standard Render View.
 *
 * Scale-consistent shading (vtkSNDFRenderPass) sits outermost in the chain when switched on, so
 * that its samples see the particles as the AO pass inside it shades them. Still renders add its
 * SamplesPerFrame samples (in the GUI the plugin's refinement behaviour renders again until
 * TargetSamples are reached), or converge at once with SNDFConvergeStillRenders (pvpython,
 * pvbatch, screenshots); interactive renders show the plain image. A pass switched off is taken
 * out of the chain and its graphics resources are released at once.
 *
 * How the next techniques plug in: a pass deriving from vtkImageProcessingPass is added with
 * `GetParticlePassChain()->AddPass(pass)` (typically from a view property setter of a subclass
 * or of this class, plus the property in the XML).
 *
 * Parallel: each rank's chain sees that rank's props and data only (IceT composites the ranks'
 * images afterwards); a pass that needs global quantities must reduce them itself. PointAO is
 * the exception the view arranges: for each distributed render it gives the pass the global
 * controller (vtkPointAOPass::SetController: the ranks' G-buffers are composited while they draw)
 * and shows a vtkParticleBoundsProp with its geometry bounds over all ranks, so that IceT, which
 * skips the draw of a rank whose props lie outside the view, draws on every rank or on none.
 * Under ordered compositing the view also owns the partition of its Particles representations
 * (vtkParticleViewPartition, in Update): one set of k-d boxes for all of them, so that ParaView's
 * cuts do not overlap and opaque particles keep their depth in the colour-only blend. With
 * density-volume or voxel-cone AO it builds, before each distributed render, one AO volume of all
 * processes' particles of all its Particles representations (vtkParticleDistributedVolumes).
 *
 * @sa vtkParticlePassChain vtkParticleRepresentation vtkPVRenderViewWithEDL
 */
#ifndef vtkParticleRenderView_h
#define vtkParticleRenderView_h

#include "vtkNew.h" // for vtkNew
#include "vtkPVRenderView.h"
#include "vtkParticleBoundsProp.h"              // for vtkNew<vtkParticleBoundsProp>
#include "vtkParticleDistributedVolumes.h"      // for vtkNew<vtkParticleDistributedVolumes>
#include "vtkParticleOrderedCompositePass.h"    // for vtkNew<vtkParticleOrderedCompositePass>
#include "vtkParticleRenderingParaViewModule.h" // for export macro
#include "vtkParticleViewPartition.h"           // for vtkNew<vtkParticleViewPartition>
#include "vtkSmartPointer.h"                    // for vtkSmartPointer

#include <string> // for std::string

class vtkAlgorithm;
class vtkImageProcessingPass;
class vtkDensityVolumeAOPass;
class vtkParticlePassChain;
class vtkPointAOPass;
class vtkSNDFRenderPass;
class vtkVoxelConeAOPass;

class VTKPARTICLERENDERINGPARAVIEW_EXPORT vtkParticleRenderView : public vtkPVRenderView
{
public:
  static vtkParticleRenderView* New();
  vtkTypeMacro(vtkParticleRenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The pass frame of this view: add particle passes to it. Its InnerPass is a vtkPVDefaultPass.
   */
  vtkParticlePassChain* GetParticlePassChain();

  /**
   * 1 when the renderer's current pass tree runs the particle pass chain (walking the FXAA,
   * image-processing and camera passes ParaView puts in front of it), 0 otherwise (e.g. while
   * OSPRay renders). Exposed as an information property for tests.
   */
  int GetParticlePassChainInstalled();

  /**
   * Number of passes in the chain (information property for tests).
   */
  int GetNumberOfParticlePasses();

  enum AmbientOcclusionMethods
  {
    NO_AMBIENT_OCCLUSION = 0,
    DENSITY_VOLUME = 1,     // vtkDensityVolumeAOPass (Grottel et al. 2012)
    VOXEL_CONE_TRACING = 2, // vtkVoxelConeAOPass (Staib et al. 2015)
    POINT_AO = 3            // vtkPointAOPass (Eichelbaum et al. 2013), screen space
  };

  ///@{
  /**
   * The view's one ambient-occlusion choice: NO_AMBIENT_OCCLUSION (default), DENSITY_VOLUME,
   * VOXEL_CONE_TRACING or POINT_AO. It puts that pass into the chain and takes the other out, so
   * that two techniques are never on at once. The passes' own settings are not forwarded by the
   * view: in ParaView each pass is a proxy of its own (group particle_passes) whose VTK object the
   * view receives through Set...AOPass (a SubProxy command), and whose properties the view exposes
   * -- the pattern every further pass follows. Without proxies (plain VTK use of this class) the
   * view has passes of its own.
   */
  void SetAmbientOcclusion(int method);
  int GetAmbientOcclusion();
  ///@}

  ///@{
  /**
   * Density-volume ambient occlusion on (DENSITY_VOLUME) or off (NO_AMBIENT_OCCLUSION when it
   * was the choice), for C++ callers of earlier versions.
   */
  void SetDensityVolumeAmbientOcclusion(int on);
  int GetDensityVolumeAmbientOcclusion();
  ///@}

  ///@{
  /**
   * The passes behind the choice (see SetAmbientOcclusion).
   */
  void SetDensityVolumeAOPass(vtkDensityVolumeAOPass* pass);
  vtkDensityVolumeAOPass* GetDensityVolumeAOPass();
  void SetVoxelConeAOPass(vtkVoxelConeAOPass* pass);
  vtkVoxelConeAOPass* GetVoxelConeAOPass();
  void SetPointAOPass(vtkPointAOPass* pass);
  vtkPointAOPass* GetPointAOPass();
  ///@}

  ///@{
  /**
   * Scale-consistent shading of sub-pixel particles (vtkSNDFRenderPass, Ibrahim et al. 2017):
   * on (1) puts the S-NDF pass outermost in the chain, so that the particles and the ambient
   * occlusion chosen above are sampled into S-NDFs; off (0, default) takes it out. While the view
   * holds still each render adds the pass's SamplesPerFrame samples per pixel; in the GUI the
   * plugin's refinement behaviour keeps rendering until TargetSamples are reached.
   */
  void SetScaleConsistentShading(int on);
  int GetScaleConsistentShading();
  ///@}

  /**
   * FXAA as the view's property asks, but off while ScaleConsistentShading is on.
   */
  void SetUseFXAA(bool use) override;

  ///@{
  /**
   * With scale-consistent shading on, every still render converges (takes all TargetSamples
   * samples at once, vtkSNDFRenderPass::ConvergeOnRender) while interactive renders stay the
   * plain image: for pvpython, pvbatch and screenshots. Off by default (the GUI refines
   * progressively instead).
   */
  vtkSetMacro(SNDFConvergeStillRenders, int);
  vtkGetMacro(SNDFConvergeStillRenders, int);
  ///@}

  ///@{
  /**
   * The speed/accuracy trade of the particle passes (vtkParticleFrameBudget): InteractiveQuality
   * ADAPTIVE (default: exact on still renders, while the camera moves the most accurate level
   * whose measured time fits the frame), EXACT or INTERACTIVE (always the cheap level), set on
   * the three ambient-occlusion passes. InteractiveFrameBudget: milliseconds an interactive render
   * may take (0, default: ParaView's own, 200 ms), set as the render window's desired update rate
   * for interactive renders, so every particle technique in the view (the representations'
   * mappers too) chooses from it.
   */
  vtkSetClampMacro(InteractiveQuality, int, 0, 2);
  vtkGetMacro(InteractiveQuality, int);
  vtkSetClampMacro(InteractiveFrameBudget, double, 0.0, 1.0e6);
  vtkGetMacro(InteractiveFrameBudget, double);
  ///@}

  /**
   * What the ambient-occlusion pass in use chose in the last frame and what its levels cost
   * (vtkParticleFrameBudget::GetLastChoiceText); empty without ambient occlusion.
   */
  const char* GetAmbientOcclusionQualityText();

  ///@{
  /**
   * The S-NDF pass behind ScaleConsistentShading (in ParaView a proxy of group particle_passes).
   */
  void SetSNDFRenderPass(vtkSNDFRenderPass* pass);
  vtkSNDFRenderPass* GetSNDFRenderPass();
  ///@}

  /**
   * The algorithm whose vtkCommand::ProgressEvent carries the progress of the view's passes (a
   * long AO volume build, vtkDensityVolumeAOPass::ProgressThreshold; a converging S-NDF render,
   * vtkSNDFRenderPass::GetProgressText), with the pass's progress
   * text. It is registered with the session's progress handler, so ParaView's progress bar shows
   * it; the representations report their mappers' work themselves.
   */
  vtkAlgorithm* GetPassProgressReporter();

  /**
   * The pass that blends the processes' images in floating point before IceT under ordered
   * compositing (in the chain, outermost, only during such renders; see
   * vtkParticleOrderedCompositePass).
   */
  vtkParticleOrderedCompositePass* GetOrderedCompositePass();

  /**
   * 1 when the last render blended the processes' images before IceT (the pass's
   * GetLastBlended()), else 0. For tests (the information property ImagesBlendedBeforeIceT).
   */
  int GetImagesBlendedBeforeIceT();

  /**
   * The view's one partition of its Particles representations under ordered compositing
   * (vtkParticleViewPartition); the representations add themselves to it.
   */
  vtkParticleViewPartition* GetViewPartition();

  /**
   * The ambient-occlusion volumes of all the view's Particles representations under distributed
   * rendering (vtkParticleDistributedVolumes): the representations tell it what they draw, the
   * view builds it before each local render.
   */
  vtkParticleDistributedVolumes* GetParticleVolumes();

  /**
   * 1 when the shown Particles representations share one partition (the last Update), else 0.
   * For tests (the information property ParticlesPartitionedTogether).
   */
  int GetParticlesPartitionedTogether();

  /**
   * The superclass's update, then the view's partition (vtkParticleViewPartition::Update, which
   * needs every representation's data and whether the view composites in order); when it
   * changed a piece on any process, the superclass's update again on all of them (the shown
   * Particles representations only deliver their pieces again).
   */
  void Update() override;

protected:
  vtkParticleRenderView();
  ~vtkParticleRenderView() override;

  /**
   * Re-installs the chain if the render-pass slot was emptied, tells the S-NDF pass whether this
   * render is to converge, sets up what composites across processes while they draw
   * (UpdateDistributedCompositing), then defers to the superclass.
   */
  void AboutToRenderOnLocalProcess(bool interactive) override;

  /**
   * The superclass's render; afterwards CompositeBounds is hidden again, so that ParaView's
   * geometry bounds (reduced in Update from the renderer's visible props too) never include it.
   */
  void Render(bool interactive, bool skip_rendering) override;

  vtkNew<vtkParticlePassChain> ParticlePassChain;
  vtkSmartPointer<vtkDensityVolumeAOPass> DensityVolumeAOPass;
  vtkSmartPointer<vtkVoxelConeAOPass> VoxelConeAOPass;
  vtkSmartPointer<vtkPointAOPass> PointAOPass;
  int AmbientOcclusion = NO_AMBIENT_OCCLUSION;
  vtkSmartPointer<vtkSNDFRenderPass> SNDFRenderPass;
  int ScaleConsistentShading = 0;
  int SNDFConvergeStillRenders = 0;
  int InteractiveQuality = 0;
  double InteractiveFrameBudget = 0.0;
  std::string AmbientOcclusionQualityText;
  bool RequestedFXAA = false; // the view's UseFXAA property (in effect without S-NDF shading)
  unsigned long PassProgressTag = 0;
  unsigned long SNDFProgressTag = 0;
  vtkNew<vtkAlgorithm> PassProgress;
  vtkNew<vtkParticleBoundsProp> CompositeBounds;
  vtkNew<vtkParticleOrderedCompositePass> OrderedComposite;
  vtkNew<vtkParticleViewPartition> ViewPartition;
  vtkNew<vtkParticleDistributedVolumes> ParticleVolumes;

private:
  vtkParticleRenderView(const vtkParticleRenderView&) = delete;
  void operator=(const vtkParticleRenderView&) = delete;

  // a pass's ProgressEvent, re-invoked by PassProgress
  void ForwardPassProgress(vtkObject* caller, unsigned long, void* callData);
  // the pass of an AO method (nullptr for none)
  vtkImageProcessingPass* GetAmbientOcclusionPass(int method);
  // Distributed renders: with PointAO the pass composites the processes' G-buffers while they
  // draw (vtkPointAOPass::SetController); with ordered compositing (translucency) the
  // processes' images are blended in floating point before IceT (OrderedComposite, outermost in
  // the chain). CompositeBounds then gives every process the view's bounds over all of them, so
  // that IceT draws on every process or on none.
  void UpdateDistributedCompositing(bool interactive);
  // the AO volume of all processes' and all Particles representations' particles, when every
  // process renders (vtkParticleDistributedVolumes)
  void UpdateDistributedVolumes(bool interactive);
  // ordered compositing of partitioned Particles representations whose actors carry the same
  // transform (and the same boxes): the order from those boxes in data coordinates
  void OrderWithTransformedPartition(int processes);
  // takes a pass out of the chain and releases its graphics resources
  void TakeOutOfChain(vtkImageProcessingPass* pass);
  // a new pass object for an AO method, swapped into the chain when that method is on
  template <typename PassType>
  void ReplaceAmbientOcclusionPass(vtkSmartPointer<PassType>& slot, PassType* pass, int method);
};

#endif
