/**
 * @class   vtkSNDFTargets
 * @brief   the view-sized render targets of vtkSNDFRenderPass: G-buffer, shaded picture, display
 *
 * The textures one sample pass of vtkSNDFRenderPass draws into and its shade writes, for a
 * rectangle of Width x Height texels (the window's pixels, or the rectangle of a view between
 * two levels of the S-MIP; class description, "Zoom between levels"):
 * - the G-buffer (Framebuffer): attachment 0 the colour as drawn (8 bits, as the window, so
 *   that the background and other geometry come out exactly as drawn without the pass), 1 and
 *   2 RGBA16F (the normal with the AO, the diffuse colour; Shaders/SNDF/SNDFAccumulate.glsl), and a
 *   32-bit float depth texture;
 * - the shaded picture (Image, RGBA32F) and its depth (ImageDepth, R32F) that the resolve
 *   writes, and the picture at the last error check (Checkpoint, RGBA32F);
 * - for a view between two levels, the window's picture and depth (DisplayImage,
 *   DisplayDepth; Shaders/SNDF/SNDFBoxFilter.glsl), made anew only when the window's size changes.
 *
 * Plain C++ (no vtkObject); vtkSNDFRenderPass holds one. TestSNDFTargets allocates them in a
 * real context and checks sizes, formats, reallocation and release.
 *
 * @sa vtkSNDFRenderPass
 */
#ifndef vtkSNDFTargets_h
#define vtkSNDFTargets_h

#include "vtkParticleRenderingSNDFModule.h" // for export macro
#include "vtkSmartPointer.h"                // for vtkSmartPointer

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGSNDF_EXPORT vtkSNDFTargets
{
public:
  // the colour attachments of the G-buffer (0: colour as drawn; see SNDFAccumulate.glsl)
  static constexpr unsigned int NumberOfAttachments = 3;

  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  vtkSmartPointer<vtkTextureObject> Attachments[NumberOfAttachments];
  vtkSmartPointer<vtkTextureObject> Depth;
  vtkSmartPointer<vtkTextureObject> Image;
  vtkSmartPointer<vtkTextureObject> ImageDepth;
  vtkSmartPointer<vtkTextureObject> Checkpoint;
  vtkSmartPointer<vtkTextureObject> DisplayImage;
  vtkSmartPointer<vtkTextureObject> DisplayDepth;
  // the texels of the G-buffer (0 when released)
  int Width = 0;
  int Height = 0;

  /**
   * The G-buffer, the shaded picture and the checkpoint made anew for a width x height
   * rectangle of texels (the display's textures released).
   */
  void Allocate(vtkOpenGLRenderWindow* context, int width, int height);

  /**
   * The window's picture and depth of a view between two levels, made anew where their size is
   * not width x height.
   */
  void AllocateDisplay(vtkOpenGLRenderWindow* context, int width, int height);

  /**
   * A float picture: RGBA, or one depth channel.
   */
  static void AllocateImage(
    vtkTextureObject* image, vtkOpenGLRenderWindow* context, int width, int height, bool depth);

  /**
   * Releases every target (Width and Height 0).
   */
  void Release(vtkWindow* w);
};

#endif
