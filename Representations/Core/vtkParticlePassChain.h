/**
 * @class   vtkParticlePassChain
 * @brief   an ordered list of wrapping render passes around one inner pass
 *
 * vtkParticlePassChain is the pass frame of vtkParticleRenderView. It is a vtkRenderPass that
 * holds an ordered list of "wrapping" passes and one inner pass:
 *
 *     chain->Render(s)  ==  Pass(0)->Render(s)
 *                             Pass(0) delegates to Pass(1)
 *                               ...
 *                                 Pass(n-1) delegates to the InnerPass
 *
 * A wrapping pass is any vtkImageProcessingPass, VTK's own type for "a vtkOpenGLRenderPass with a
 * DelegatePass" (vtkSSAOPass, vtkEDLShading, vtkToneMappingPass, vtkOpenGLFXAAPass are examples).
 * Particle techniques that need to run work before or after the scene (a visibility or
 * occlusion pre-pass, a compositing post-pass) or to reach the sphere shaders through
 * vtkOpenGLRenderPass::PreReplaceShaderValues / PostReplaceShaderValues derive from it and call
 * their DelegatePass (directly, or via vtkImageProcessingPass::RenderDelegate into an FBO) where
 * the scene should be drawn. The chain sets every DelegatePass itself: whenever the list changes
 * and again at each Render() (a no-op when nothing changed), so a pass must not be shared
 * between two chains.
 *
 * The InnerPass renders the scene. In ParaView it is a vtkPVDefaultPass (set by
 * vtkParticleRenderView): lights, opaque and translucent geometry (with ParaView's depth
 * peeling), volumes and overlays exactly as the standard Render View, including the renderer's
 * own SSAO ("Use Ambient Occlusion"). In a plain VTK program use a vtkRenderStepsPass inside a
 * vtkCameraPass, or put the chain under a vtkCameraPass and give it a pass that does what
 * vtkPVDefaultPass does. With no wrapping pass the chain renders exactly what the InnerPass
 * renders. Without an InnerPass it renders nothing (with one warning).
 *
 * The class needs VTK only and lives in ParticleRendering::Core (the view of the ParaView module
 * uses it); the passes it holds may live anywhere (the technique modules included), since their
 * interface is VTK's vtkImageProcessingPass.
 *
 * @sa vtkParticleRenderView vtkImageProcessingPass vtkPVDefaultPass
 */
#ifndef vtkParticlePassChain_h
#define vtkParticlePassChain_h

#include "vtkParticleRenderingCoreModule.h" // for export macro
#include "vtkRenderPass.h"

class vtkImageProcessingPass;

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticlePassChain : public vtkRenderPass
{
public:
  static vtkParticlePassChain* New();
  vtkTypeMacro(vtkParticlePassChain, vtkRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The pass that renders the scene, innermost in the chain. Default: none (vtkParticleRenderView
   * sets a vtkPVDefaultPass).
   */
  virtual void SetInnerPass(vtkRenderPass* pass);
  vtkGetObjectMacro(InnerPass, vtkRenderPass);
  ///@}

  ///@{
  /**
   * The wrapping passes, outermost first. AddPass appends (the new pass becomes the innermost
   * wrapping pass, directly around the InnerPass); InsertPass puts it at `index` (0 = outermost).
   * A pass already in the chain or a null pass is refused (false). RemovePass / RemoveAllPasses
   * unlink the removed passes (their DelegatePass becomes null).
   */
  bool AddPass(vtkImageProcessingPass* pass);
  bool InsertPass(int index, vtkImageProcessingPass* pass);
  bool RemovePass(vtkImageProcessingPass* pass);
  void RemoveAllPasses();
  int GetNumberOfPasses() const;
  vtkImageProcessingPass* GetPass(int index) const;
  bool HasPass(vtkImageProcessingPass* pass) const;
  ///@}

  /**
   * Render the outermost wrapping pass (or the InnerPass when there is none).
   * NumberOfRenderedProps is the one of the pass that was rendered.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Release the graphics resources of every pass of the chain and of the InnerPass.
   */
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkParticlePassChain();
  ~vtkParticlePassChain() override;

  /**
   * Set each pass's DelegatePass to the next one, the last one's to the InnerPass.
   */
  void LinkPasses();

  vtkRenderPass* InnerPass = nullptr;
  bool WarnedNoInnerPass = false;

private:
  vtkParticlePassChain(const vtkParticlePassChain&) = delete;
  void operator=(const vtkParticlePassChain&) = delete;

  class vtkInternals;
  vtkInternals* Internals;
};

#endif
