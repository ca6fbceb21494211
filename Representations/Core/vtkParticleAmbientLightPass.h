/**
 * @class   vtkParticleAmbientLightPass
 * @brief   base of the render passes that change the ambient light the particles receive
 *
 * vtkParticleAmbientLightPass is the contract between a pass that adds ambient occlusion or
 * ambient illumination to the particles and the other passes of the chain that need to know how
 * (vtkSNDFRenderPass, which shades its samples itself). It is a vtkImageProcessingPass and adds
 * two questions a subclass answers:
 *
 * - GetOcclusionSpace(): PER_FRAGMENT if the occlusion reaches the particle shaders through their
 *   hooks (object-space volumes: the shaders sample it at every fragment, Staib et al. 2015
 *   Eq. 3-7, Grottel et al. 2012), SCREEN_SPACE if it darkens the composited pixels after the
 *   scene (vtkPointAOPass, from the depth buffer). A pass that shades its own samples can only
 *   use the former.
 * - GetAddsColouredAmbientLight(): whether the ambient term carries the particles' colours
 *   (the voxel-cone pass's L_A, Eq. 7), so that a pass recolouring particles must rebuild it.
 *
 * The core knows no technique: passes and mappers talk through this base and
 * vtkParticleSphereMapper's virtuals, never through each other's headers.
 *
 * @sa vtkParticleVolumeAOPass vtkPointAOPass vtkSNDFRenderPass vtkImageProcessingPass
 */
#ifndef vtkParticleAmbientLightPass_h
#define vtkParticleAmbientLightPass_h

#include "vtkImageProcessingPass.h"
#include "vtkNew.h"                         // for vtkNew
#include "vtkParticleFrameBudget.h"         // for vtkNew<vtkParticleFrameBudget>
#include "vtkParticleRenderingCoreModule.h" // for export macro

#include <string> // for std::string

class VTKPARTICLERENDERINGCORE_EXPORT vtkParticleAmbientLightPass : public vtkImageProcessingPass
{
public:
  vtkTypeMacro(vtkParticleAmbientLightPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum OcclusionSpaces
  {
    PER_FRAGMENT = 0,
    SCREEN_SPACE = 1
  };

  /**
   * Where the occlusion is applied: PER_FRAGMENT (in the particle shaders) or SCREEN_SPACE
   * (on the composited image).
   */
  virtual int GetOcclusionSpace() = 0;

  /**
   * Whether the ambient light carries the particles' colours (default false).
   */
  virtual bool GetAddsColouredAmbientLight();

  /**
   * The pass's quality while the camera moves: its quality setting (ADAPTIVE, EXACT,
   * INTERACTIVE), the GPU times it measured per level and its last choice (see
   * vtkParticleFrameBudget and the subclass's description of its levels).
   */
  vtkParticleFrameBudget* GetFrameBudget() { return this->FrameBudget; }

  /**
   * The names of the quality levels with the current settings, cheapest first, separated by '|'
   * ("exact" by default), and one line saying which the last frame drew, why, and what each cost
   * (vtkParticleFrameBudget::GetLastChoiceText).
   */
  virtual std::string GetQualityLevelNames() { return "exact"; }
  std::string GetQualityText()
  {
    return this->FrameBudget->GetLastChoiceText(this->GetQualityLevelNames());
  }

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkParticleAmbientLightPass() = default;
  ~vtkParticleAmbientLightPass() override = default;

  vtkNew<vtkParticleFrameBudget> FrameBudget;

private:
  vtkParticleAmbientLightPass(const vtkParticleAmbientLightPass&) = delete;
  void operator=(const vtkParticleAmbientLightPass&) = delete;
};

#endif
