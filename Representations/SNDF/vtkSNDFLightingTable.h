/**
 * @class   vtkSNDFLightingTable
 * @brief   the lighting table of vtkSNDFRenderPass: the lit value per bin of the normal disk
 *
 * The S-NDF paper (Ibrahim et al. 2017, Eqs. 12-14) shades a pixel from its bins' counts and a
 * table of the lighting integrated over each bin. This table holds, per bin of the disk of view
 * normals (Shaders/SNDF/SNDFBins.glsl) and for the renderer's lights and the specular power, Rows
 * rows: the diffuse D and specular S sums, their slopes in u.x and u.y (the least-squares plane
 * of the lit value over the part of the bin inside the disk) and the bin's centroid
 * (vtkSNDFRenderPass's class description). Build() renders it in a full-screen quad
 * (Shaders/SNDF/SNDFLightingTable.glsl with the lights' code of vtkParticleSphereMapper) into an
 * RGBA32F texture of bins^2 x Rows texels; it is built again only when its key (what it
 * depends on: the lights, the specular power, the bins) changes (IsCurrent()). Read() copies it
 * out (vtkSNDFRenderPass::GetLightingTable).
 *
 * Plain C++ (no vtkObject); vtkSNDFRenderPass holds one. The Python tests read the table
 * through vtkSNDFRenderPass::GetLightingTable.
 *
 * @sa vtkSNDFRenderPass vtkSNDFTileCache
 */
#ifndef vtkSNDFLightingTable_h
#define vtkSNDFLightingTable_h

#include "vtkNew.h"                         // for vtkNew
#include "vtkParticleRenderingSNDFModule.h" // for export macro

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkCamera;
class vtkFloatArray;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOpenGLRenderer;
class vtkProperty;
class vtkTextureObject;
class vtkWindow;

class VTKPARTICLERENDERINGSNDF_EXPORT vtkSNDFLightingTable
{
public:
  // rows per bin (SNDFBins.glsl): D, S, their slopes in u.x and u.y, the centroid
  static constexpr int Rows = 7;
  // sub-samples per axis of the whole [-1, 1] square (per bin: this over the bins per axis, at
  // least 32)
  static constexpr int SubsamplesPerAxis = 512;

  vtkSNDFLightingTable();
  ~vtkSNDFLightingTable();
  vtkSNDFLightingTable(const vtkSNDFLightingTable&) = delete;
  vtkSNDFLightingTable& operator=(const vtkSNDFLightingTable&) = delete;

  /**
   * Whether the table is built for `key`.
   */
  bool IsCurrent(const std::vector<double>& key) const { return this->Have && key == this->Key; }

  /**
   * Builds the table for the renderer's lights (their uniforms brought up to date by its lights
   * pass), `material`'s specular power, `camera`'s distance (positional lights) and `bins` per
   * axis, and keeps `key`. False where its shader did not build.
   */
  bool Build(vtkOpenGLRenderer* ren, vtkOpenGLRenderWindow* context, vtkCamera* camera,
    vtkProperty* material, int bins, const std::vector<double>& key);

  /**
   * The table as Rows * bins^2 RGB tuples (row-major: bins^2 per row); false where none is
   * built.
   */
  bool Read(vtkFloatArray* table);

  /**
   * The table's texture (bins^2 x Rows, RGBA32F).
   */
  vtkTextureObject* GetTexture() const;

  /**
   * Releases the texture, its framebuffer and the shader; the next Build() builds anew.
   */
  void Release(vtkWindow* w);

private:
  vtkNew<vtkOpenGLFramebufferObject> Target;
  vtkNew<vtkTextureObject> Table;
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  std::string QuadSource;
  bool Have = false;
  int Bins = 0;
  std::vector<double> Key;
};

#endif
