#include "vtkParticleOcclusionCuller.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkTimerLog.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

vtkStandardNewMacro(vtkParticleOcclusionCuller);

namespace
{
// the phases: the nearest cells holding these cumulative shares of the particles are drawn
// before each depth read-back (the last phase draws the rest)
constexpr double PhaseEnds[] = { 1.0 / 32.0, 1.0 / 8.0, 3.0 / 8.0, 1.0 };
constexpr int NumberOfPhases = static_cast<int>(sizeof(PhaseEnds) / sizeof(PhaseEnds[0]));

struct CellBox
{
  double Min[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double Max[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
  double MaxRadius = 0.0;
  vtkIdType First = 0; // offset into the index buffer
  vtkIdType Count = 0;
};

// a cell seen from the camera this frame
struct CellView
{
  double Nearest = 0.0;         // smallest window depth of the box
  int Rect[4] = { 0, 0, 0, 0 }; // block range x0, y0, x1, y1 (inclusive)
  bool Unbounded = false;       // a corner at or behind the eye plane: always drawn
  bool Outside = false;         // outside the viewport or beyond the far plane
};

// position i in double: float and double arrays without virtual calls, others through GetTuple
void GetPosition(vtkDataArray* positions, vtkIdType i, double p[3])
{
  if (auto* f = vtkFloatArray::FastDownCast(positions))
  {
    const float* q = f->GetPointer(3 * i);
    p[0] = q[0];
    p[1] = q[1];
    p[2] = q[2];
  }
  else if (auto* d = vtkDoubleArray::FastDownCast(positions))
  {
    const double* q = d->GetPointer(3 * i);
    p[0] = q[0];
    p[1] = q[1];
    p[2] = q[2];
  }
  else
  {
    positions->GetTuple(i, p);
  }
}

// the sphere core draws a particle with a positive finite radius at a finite position
bool IsDrawn(float radius, const double p[3])
{
  return radius > 0.0f && std::isfinite(radius) && std::isfinite(p[0]) && std::isfinite(p[1]) &&
    std::isfinite(p[2]);
}

// Can the bound framebuffer's depth tell hidden cells exactly? Depth test and writes on, GL_LESS or
// GL_LEQUAL, depth range [0, 1], a depth buffer, no multisampling (glReadPixels cannot read it).
// vp: the current viewport.
bool DepthAllowsCulling(vtkOpenGLState* ostate, int vp[4])
{
  GLint depthFunc = GL_LESS;
  ostate->vtkglGetIntegerv(GL_DEPTH_FUNC, &depthFunc);
  unsigned char depthMask = 0;
  ostate->vtkglGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  GLfloat depthRange[2] = { 0.0f, 1.0f };
  glGetFloatv(GL_DEPTH_RANGE, depthRange);
  GLint samples = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  GLint depthBits = 0;
  {
    unsigned int drawFramebuffer = 0;
    unsigned int drawBuffer = 0;
    ostate->GetCurrentDrawFramebufferState(drawFramebuffer, drawBuffer);
    if (drawFramebuffer == 0)
    {
      glGetFramebufferAttachmentParameteriv(
        GL_DRAW_FRAMEBUFFER, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
    }
    else
    {
      GLint type = GL_NONE;
      glGetFramebufferAttachmentParameteriv(
        GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
      if (type != GL_NONE)
      {
        glGetFramebufferAttachmentParameteriv(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
          GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &depthBits);
      }
    }
  }
  ostate->vtkglGetIntegerv(GL_VIEWPORT, vp);
  return ostate->GetEnumState(GL_DEPTH_TEST) && depthMask &&
    (depthFunc == GL_LESS || depthFunc == GL_LEQUAL) && depthRange[0] == 0.0f &&
    depthRange[1] == 1.0f && samples == 0 && depthBits > 0 && vp[2] > 0 && vp[3] > 0;
}
}

//------------------------------------------------------------------------------
class vtkParticleOcclusionCuller::vtkInternals
{
public:
  std::vector<CellBox> Cells;
  vtkNew<vtkOpenGLBufferObject> Indices;
  vtkNew<vtkTextureObject> BlockTexture; // BlockMax for the geometry stage's per-sphere test
  vtkOpenGLRenderWindow* Context = nullptr;
  vtkIdType TotalCount = 0; // all particles, drawn or not, for the plain draw
  std::vector<float> Depth;
  std::vector<float> BlockMax;
  int Blocks[2] = { 0, 0 };
  // per-frame scratch
  std::vector<CellView> Views;
  std::vector<int> Order;
  std::vector<GLsizei> Counts;
  std::vector<const void*> Offsets;

  void ReadDepth(vtkOpenGLState* ostate, const int vp[4], int block);
  // binds BlockTexture (a 1x1 far-plane map until the first read-back) to the program's
  // prOcclusionMap with the test off: the sampler needs a unit of its own even while unused
  void BindMap(vtkOpenGLRenderWindow* ctx, vtkShaderProgram* program);
  void UploadMap();
  void UnbindMap(vtkShaderProgram* program);
  bool MapBound = false;
  GLuint Query = 0; // GL_PRIMITIVES_GENERATED (CountEmittedSpheres)
  bool Hidden(const CellView& view, double margin) const;
  // Views: each cell's projection (Nearest, block Rect, Unbounded, Outside) for this frame
  void ProjectCells(const double m[4][4], const double wcdc[4][4], double radiusScaleWC,
    const int vp[4], int block);
  void DrawCells(const int* cells, int n, vtkIdType& drawnParticles, int& drawnCells);
};

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::vtkInternals::ReadDepth(
  vtkOpenGLState* ostate, const int vp[4], int block)
{
  const int w = vp[2];
  const int h = vp[3];
  this->Depth.resize(static_cast<size_t>(w) * static_cast<size_t>(h));
  unsigned int drawFramebuffer = 0;
  unsigned int drawBuffer = 0;
  ostate->GetCurrentDrawFramebufferState(drawFramebuffer, drawBuffer);
  ostate->PushReadFramebufferBinding();
  ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, drawFramebuffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(vp[0], vp[1], w, h, GL_DEPTH_COMPONENT, GL_FLOAT, this->Depth.data());
  ostate->PopReadFramebufferBinding();

  const int bw = (w + block - 1) / block;
  const int bh = (h + block - 1) / block;
  this->Blocks[0] = bw;
  this->Blocks[1] = bh;
  this->BlockMax.assign(static_cast<size_t>(bw) * static_cast<size_t>(bh), 0.0f);
  const float* depth = this->Depth.data();
  float* blockMax = this->BlockMax.data();
  vtkSMPTools::For(0, bh,
    [&](int begin, int end)
    {
      for (int by = begin; by < end; ++by)
      {
        float* row = blockMax + static_cast<size_t>(by) * bw;
        const int y1 = std::min(h, (by + 1) * block);
        for (int y = by * block; y < y1; ++y)
        {
          const float* line = depth + static_cast<size_t>(y) * w;
          for (int x = 0; x < w; ++x)
          {
            // a NaN depth counts as the far plane (nothing hides behind it)
            const float d = line[x] == line[x] ? line[x] : 1.0f;
            float& m = row[x / block];
            m = d > m ? d : m;
          }
        }
      }
    });
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::vtkInternals::BindMap(
  vtkOpenGLRenderWindow* ctx, vtkShaderProgram* program)
{
  this->MapBound = false;
  if (!program || !program->IsUniformUsed("prOcclusionMap"))
  {
    return;
  }
  vtkTextureObject* texture = this->BlockTexture;
  if (texture->GetContext() != ctx || !texture->GetHandle())
  {
    texture->ReleaseGraphicsResources(ctx);
    texture->SetContext(ctx);
    this->Blocks[0] = this->Blocks[1] = 1;
    this->BlockMax.assign(1, 1.0f);
    this->UploadMap();
  }
  texture->Activate();
  program->SetUniformi("prOcclusionMap", texture->GetTextureUnit());
  program->SetUniformi("prOcclusionCull", 0);
  this->MapBound = true;
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::vtkInternals::UploadMap()
{
  vtkTextureObject* texture = this->BlockTexture;
  if (texture->GetWidth() != static_cast<unsigned int>(this->Blocks[0]) ||
    texture->GetHeight() != static_cast<unsigned int>(this->Blocks[1]) || !texture->GetHandle())
  {
    const bool active = texture->GetTextureUnit() >= 0;
    vtkOpenGLRenderWindow* ctx = texture->GetContext();
    texture->Deactivate();
    texture->ReleaseGraphicsResources(ctx);
    texture->SetContext(ctx);
    texture->SetInternalFormat(GL_R32F);
    texture->SetFormat(GL_RED);
    texture->SetDataType(GL_FLOAT);
    texture->SetMinificationFilter(vtkTextureObject::Nearest);
    texture->SetMagnificationFilter(vtkTextureObject::Nearest);
    texture->Create2DFromRaw(this->Blocks[0], this->Blocks[1], 1, VTK_FLOAT, this->BlockMax.data());
    if (active)
    {
      texture->Activate();
    }
  }
  else
  {
    texture->Bind();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, this->Blocks[0], this->Blocks[1], GL_RED, GL_FLOAT,
      this->BlockMax.data());
  }
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::vtkInternals::UnbindMap(vtkShaderProgram* program)
{
  if (this->MapBound)
  {
    program->SetUniformi("prOcclusionCull", 0);
    this->BlockTexture->Deactivate();
    this->MapBound = false;
  }
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::vtkInternals::ProjectCells(
  const double m[4][4], const double wcdc[4][4], double radiusScaleWC, const int vp[4], int block)
{
  // each cell's box in world coordinates (m: model -> world), grown by its largest radius,
  // projected (wcdc: world -> clip)
  const int bw = (vp[2] + block - 1) / block;
  const int bh = (vp[3] + block - 1) / block;
  const int numCells = static_cast<int>(this->Cells.size());
  this->Views.resize(static_cast<size_t>(numCells));
  vtkSMPTools::For(0, numCells,
    [&](int begin, int end)
    {
      for (int c = begin; c < end; ++c)
      {
        const CellBox& cell = this->Cells[c];
        CellView& view = this->Views[c];
        view = CellView();
        if (cell.Count == 0)
        {
          view.Outside = true;
          continue;
        }
        double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
        double hi[3] = { VTK_DOUBLE_MIN, VTK_DOUBLE_MIN, VTK_DOUBLE_MIN };
        for (int corner = 0; corner < 8; ++corner)
        {
          const double p[3] = { (corner & 1) ? cell.Max[0] : cell.Min[0],
            (corner & 2) ? cell.Max[1] : cell.Min[1], (corner & 4) ? cell.Max[2] : cell.Min[2] };
          for (int k = 0; k < 3; ++k)
          {
            const double w = m[k][0] * p[0] + m[k][1] * p[1] + m[k][2] * p[2] + m[k][3];
            lo[k] = std::min(lo[k], w);
            hi[k] = std::max(hi[k], w);
          }
        }
        const double grow = 1.001 * cell.MaxRadius * radiusScaleWC;
        double x0 = VTK_DOUBLE_MAX, y0 = VTK_DOUBLE_MAX, x1 = VTK_DOUBLE_MIN, y1 = VTK_DOUBLE_MIN;
        double zmin = VTK_DOUBLE_MAX;
        double zmax = VTK_DOUBLE_MIN;
        int behind = 0; // corners at or behind the eye plane
        for (int corner = 0; corner < 8; ++corner)
        {
          const double p[3] = { (corner & 1) ? hi[0] + grow : lo[0] - grow,
            (corner & 2) ? hi[1] + grow : lo[1] - grow,
            (corner & 4) ? hi[2] + grow : lo[2] - grow };
          double clip[4];
          for (int k = 0; k < 4; ++k)
          {
            clip[k] = wcdc[k][0] * p[0] + wcdc[k][1] * p[1] + wcdc[k][2] * p[2] + wcdc[k][3];
          }
          if (!std::isfinite(clip[3]))
          {
            behind = -8; // no usable projection: draw the cell
            break;
          }
          if (!(clip[3] > 1e-12 * (std::abs(clip[0]) + std::abs(clip[1]) + std::abs(clip[2]))))
          {
            ++behind; // at or behind the eye plane: no bounded projection
            continue;
          }
          const double nx = clip[0] / clip[3];
          const double ny = clip[1] / clip[3];
          const double nz = clip[2] / clip[3];
          x0 = std::min(x0, nx);
          x1 = std::max(x1, nx);
          y0 = std::min(y0, ny);
          y1 = std::max(y1, ny);
          zmin = std::min(zmin, nz);
          zmax = std::max(zmax, nz);
        }
        if (behind == 8)
        {
          view.Outside = true; // the whole box behind the eye (perspective): never seen
          continue;
        }
        if (behind != 0)
        {
          view.Unbounded = true; // straddles the eye plane: drawn first, never culled
          view.Nearest = -1.0;
          continue;
        }
        if (x1 < -1.0 || x0 > 1.0 || y1 < -1.0 || y0 > 1.0 || zmin > 1.0 || zmax < -1.0)
        {
          view.Outside = true;
          continue;
        }
        view.Nearest = 0.5 * (std::max(zmin, -1.0) + 1.0);
        // pixels of the viewport, grown by one, as blocks
        const double px0 = (x0 + 1.0) * 0.5 * vp[2] - 1.0;
        const double px1 = (x1 + 1.0) * 0.5 * vp[2] + 1.0;
        const double py0 = (y0 + 1.0) * 0.5 * vp[3] - 1.0;
        const double py1 = (y1 + 1.0) * 0.5 * vp[3] + 1.0;
        view.Rect[0] = static_cast<int>(std::max(0.0, std::floor(px0 / block)));
        view.Rect[1] = static_cast<int>(std::max(0.0, std::floor(py0 / block)));
        view.Rect[2] = static_cast<int>(std::min(bw - 1.0, std::floor(px1 / block)));
        view.Rect[3] = static_cast<int>(std::min(bh - 1.0, std::floor(py1 / block)));
      }
    });
}

//------------------------------------------------------------------------------
bool vtkParticleOcclusionCuller::vtkInternals::Hidden(const CellView& view, double margin) const
{
  if (view.Unbounded)
  {
    return false;
  }
  const double limit = view.Nearest - margin;
  for (int by = view.Rect[1]; by <= view.Rect[3]; ++by)
  {
    const float* row = this->BlockMax.data() + static_cast<size_t>(by) * this->Blocks[0];
    for (int bx = view.Rect[0]; bx <= view.Rect[2]; ++bx)
    {
      if (!(static_cast<double>(row[bx]) < limit))
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::vtkInternals::DrawCells(
  const int* cells, int n, vtkIdType& drawnParticles, int& drawnCells)
{
  this->Counts.clear();
  this->Offsets.clear();
  vtkIdType nextFirst = -1;
  for (int i = 0; i < n; ++i)
  {
    const CellBox& cell = this->Cells[cells[i]];
    if (cell.Count == 0)
    {
      continue;
    }
    drawnParticles += cell.Count;
    ++drawnCells;
    if (cell.First == nextFirst && !this->Counts.empty())
    {
      this->Counts.back() += static_cast<GLsizei>(cell.Count); // contiguous: one range
    }
    else
    {
      this->Counts.push_back(static_cast<GLsizei>(cell.Count));
      this->Offsets.push_back(
        reinterpret_cast<const void*>(static_cast<size_t>(cell.First) * sizeof(GLuint)));
    }
    nextFirst = cell.First + cell.Count;
  }
  if (!this->Counts.empty())
  {
    glMultiDrawElements(GL_POINTS, this->Counts.data(), GL_UNSIGNED_INT, this->Offsets.data(),
      static_cast<GLsizei>(this->Counts.size()));
  }
}

//------------------------------------------------------------------------------
vtkParticleOcclusionCuller::vtkParticleOcclusionCuller()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleOcclusionCuller::~vtkParticleOcclusionCuller()
{
  delete this->Internals;
}

//------------------------------------------------------------------------------
bool vtkParticleOcclusionCuller::Build(
  vtkRenderer* ren, vtkDataArray* positions, const float* radii, vtkIdType count)
{
  vtkInternals& internals = *this->Internals;
  internals.Cells.clear();
  internals.TotalCount = count;
  this->NumberOfCells = 0;
  this->NumberOfParticles = 0;
  if (!positions || count <= 0 || positions->GetNumberOfTuples() < count)
  {
    return true;
  }

  // positions in double (any precision; float and double without virtual calls)
  auto position = [positions](vtkIdType i, double p[3]) { GetPosition(positions, i, p); };
  auto valid = [&](vtkIdType i, const double p[3]) { return IsDrawn(radii[i], p); };

  double bounds[6] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN, VTK_DOUBLE_MAX, VTK_DOUBLE_MIN,
    VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  vtkIdType validCount = 0;
  for (vtkIdType i = 0; i < count; ++i)
  {
    double p[3];
    position(i, p);
    if (!valid(i, p))
    {
      continue;
    }
    ++validCount;
    for (int k = 0; k < 3; ++k)
    {
      bounds[2 * k] = std::min(bounds[2 * k], p[k]);
      bounds[2 * k + 1] = std::max(bounds[2 * k + 1], p[k]);
    }
  }
  if (validCount == 0)
  {
    return true;
  }

  // cell grid: about ParticlesPerCell per cell, cubic cells over the extended axes
  const double target = std::max(1.0,
    std::min(static_cast<double>(this->MaximumNumberOfCells),
      static_cast<double>(validCount) / static_cast<double>(this->ParticlesPerCell)));
  double extent[3];
  double largest = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    extent[k] = bounds[2 * k + 1] - bounds[2 * k];
    largest = std::max(largest, extent[k]);
  }
  int dims[3] = { 1, 1, 1 };
  if (largest > 0.0 && std::isfinite(largest))
  {
    double volume = 1.0;
    int axes = 0;
    for (int k = 0; k < 3; ++k)
    {
      if (extent[k] > 1e-9 * largest)
      {
        volume *= extent[k];
        ++axes;
      }
    }
    double side = std::pow(volume / target, 1.0 / axes);
    for (int attempt = 0; attempt < 64; ++attempt)
    {
      double cells = 1.0;
      for (int k = 0; k < 3; ++k)
      {
        dims[k] = extent[k] > 1e-9 * largest
          ? static_cast<int>(std::max(1.0, std::min(1024.0, std::floor(extent[k] / side))))
          : 1;
        cells *= dims[k];
      }
      if (cells <= this->MaximumNumberOfCells)
      {
        break;
      }
      side *= 1.1;
    }
  }
  double scale[3];
  for (int k = 0; k < 3; ++k)
  {
    scale[k] = extent[k] > 0.0 ? dims[k] / extent[k] : 0.0;
  }
  try
  {
    return this->BuildCells(ren, positions, radii, count, validCount, bounds, dims, scale);
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorMacro(<< "Not enough memory for the occlusion culling of " << count
                  << " particles (about " << (8 * count) / (1 << 20)
                  << " MB of indices): they are drawn unculled.");
    internals.Cells.clear();
    this->NumberOfCells = 0;
    return false;
  }
}

//------------------------------------------------------------------------------
bool vtkParticleOcclusionCuller::BuildCells(vtkRenderer* ren, vtkDataArray* positions,
  const float* radii, vtkIdType count, vtkIdType validCount, const double bounds[6],
  const int dims[3], const double scale[3])
{
  vtkInternals& internals = *this->Internals;
  const int numCells = dims[0] * dims[1] * dims[2];
  auto position = [positions](vtkIdType i, double p[3]) { GetPosition(positions, i, p); };
  auto valid = [&](vtkIdType i, const double p[3]) { return IsDrawn(radii[i], p); };
  std::vector<int> cellOf(static_cast<size_t>(count), -1);
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double p[3];
        position(i, p);
        if (!valid(i, p))
        {
          continue;
        }
        int c[3];
        for (int k = 0; k < 3; ++k)
        {
          c[k] =
            std::min(dims[k] - 1, std::max(0, static_cast<int>((p[k] - bounds[2 * k]) * scale[k])));
        }
        cellOf[i] = c[0] + dims[0] * (c[1] + dims[1] * c[2]);
      }
    });

  // counting sort into cell order, cell boxes
  internals.Cells.assign(static_cast<size_t>(numCells), CellBox());
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (cellOf[i] >= 0)
    {
      internals.Cells[cellOf[i]].Count++;
    }
  }
  vtkIdType first = 0;
  for (CellBox& cell : internals.Cells)
  {
    cell.First = first;
    first += cell.Count;
  }
  std::vector<unsigned int> indices(static_cast<size_t>(validCount));
  std::vector<vtkIdType> fill(static_cast<size_t>(numCells));
  for (int c = 0; c < numCells; ++c)
  {
    fill[c] = internals.Cells[c].First;
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    const int c = cellOf[i];
    if (c < 0)
    {
      continue;
    }
    indices[fill[c]++] = static_cast<unsigned int>(i);
    CellBox& cell = internals.Cells[c];
    double p[3];
    position(i, p);
    for (int k = 0; k < 3; ++k)
    {
      cell.Min[k] = std::min(cell.Min[k], p[k]);
      cell.Max[k] = std::max(cell.Max[k], p[k]);
    }
    cell.MaxRadius = std::max(cell.MaxRadius, static_cast<double>(radii[i]));
  }

  vtkOpenGLRenderWindow* ctx = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (internals.Context && internals.Context != ctx)
  {
    internals.Indices->ReleaseGraphicsResources();
  }
  internals.Context = ctx;
  if (!internals.Indices->Upload(indices, vtkOpenGLBufferObject::ElementArrayBuffer))
  {
    vtkErrorMacro(<< "Cannot upload the " << validCount
                  << " particle indices of the occlusion culling; particles are drawn unculled.");
    internals.Cells.clear();
    return false;
  }
  internals.Indices->Release();
  this->NumberOfCells = numCells;
  this->NumberOfParticles = validCount;
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleOcclusionCuller::Draw(vtkRenderer* ren, vtkShaderProgram* program,
  vtkMatrix4x4* wcdcTransposed, vtkMatrix4x4* mcwc, double radiusScaleWC)
{
  vtkInternals& internals = *this->Internals;
  this->LastNumberOfDrawnParticles = 0;
  this->LastNumberOfDrawnCells = 0;
  this->LastNumberOfDepthReads = 0;
  this->LastCullSeconds = 0.0;
  const int numCells = static_cast<int>(internals.Cells.size());
  vtkOpenGLRenderWindow* ctx = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());

  auto plainDraw = [&]()
  {
    this->DrawAll(ren, program, internals.TotalCount);
    return false;
  };
  if (numCells == 0 || !ctx || ctx != internals.Context)
  {
    return plainDraw();
  }

  vtkOpenGLState* ostate = ctx->GetState();
  int vp[4] = { 0, 0, 0, 0 };
  if (!DepthAllowsCulling(ostate, vp))
  {
    return plainDraw();
  }

  const double start = vtkTimerLog::GetUniversalTime();
  // model -> clip (row-major, points as columns); wcdc from the camera is stored transposed
  double wcdc[4][4];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      wcdc[i][j] = wcdcTransposed->GetElement(j, i);
    }
  }
  double m[4][4];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      m[i][j] = mcwc ? mcwc->GetElement(i, j) : (i == j ? 1.0 : 0.0);
    }
  }

  const int block = this->BlockSize;
  internals.ProjectCells(m, wcdc, radiusScaleWC, vp, block);

  // nearest first
  internals.Order.clear();
  for (int c = 0; c < numCells; ++c)
  {
    if (!internals.Views[c].Outside)
    {
      internals.Order.push_back(c);
    }
  }
  std::sort(internals.Order.begin(), internals.Order.end(),
    [&](int a, int b) { return internals.Views[a].Nearest < internals.Views[b].Nearest; });

  internals.Indices->Bind(); // the element array of the caller's vertex array
  double cullSeconds = vtkTimerLog::GetUniversalTime() - start;
  vtkIdType drawn = 0;
  int drawnCells = 0;
  const double total = static_cast<double>(this->NumberOfParticles);
  size_t next = 0;
  vtkIdType planned = 0;
  std::vector<int> phaseCells;
  internals.BindMap(ctx, program);
  this->BeginCount();
  for (int phase = 0; phase < NumberOfPhases && next < internals.Order.size(); ++phase)
  {
    const size_t begin = next;
    const double end = PhaseEnds[phase] * total;
    while (next < internals.Order.size() &&
      (phase == NumberOfPhases - 1 || static_cast<double>(planned) < end || next == begin))
    {
      planned += internals.Cells[internals.Order[next]].Count;
      ++next;
    }
    phaseCells.clear();
    if (phase == 0 && !this->DepthPrimed)
    {
      phaseCells.assign(internals.Order.begin() + begin, internals.Order.begin() + next);
    }
    else
    {
      const double t0 = vtkTimerLog::GetUniversalTime();
      internals.ReadDepth(ostate, vp, block);
      ++this->LastNumberOfDepthReads;
      for (size_t i = begin; i < next; ++i)
      {
        const int c = internals.Order[i];
        if (!internals.Hidden(internals.Views[c], this->DepthMargin))
        {
          phaseCells.push_back(c);
        }
      }
      if (internals.MapBound)
      {
        internals.UploadMap();
        program->SetUniformi("prOcclusionMap", internals.BlockTexture->GetTextureUnit());
        program->SetUniformi("prOcclusionCull", 1);
        const float viewport[2] = { static_cast<float>(vp[2]), static_cast<float>(vp[3]) };
        program->SetUniform2f("prOcclusionViewport", viewport);
        program->SetUniformf("prOcclusionBlock", static_cast<float>(block));
        program->SetUniformf("prOcclusionMargin", static_cast<float>(this->DepthMargin));
      }
      cullSeconds += vtkTimerLog::GetUniversalTime() - t0;
    }
    internals.DrawCells(phaseCells.data(), static_cast<int>(phaseCells.size()), drawn, drawnCells);
  }
  internals.Indices->Release();
  this->EndCount();
  internals.UnbindMap(program);
  this->LastNumberOfDrawnParticles = drawn;
  this->LastNumberOfDrawnCells = drawnCells;
  this->LastCullSeconds = cullSeconds;
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::BeginCount()
{
  this->LastNumberOfEmittedSpheres = -1;
  if (this->CountEmittedSpheres)
  {
    if (!this->Internals->Query)
    {
      glGenQueries(1, &this->Internals->Query);
    }
    glBeginQuery(GL_PRIMITIVES_GENERATED, this->Internals->Query);
  }
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::EndCount()
{
  if (this->CountEmittedSpheres)
  {
    glEndQuery(GL_PRIMITIVES_GENERATED);
    GLuint64 primitives = 0;
    glGetQueryObjectui64v(this->Internals->Query, GL_QUERY_RESULT, &primitives);
    this->LastNumberOfEmittedSpheres = static_cast<vtkIdType>(primitives);
  }
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::DrawAll(
  vtkRenderer* ren, vtkShaderProgram* program, vtkIdType count)
{
  vtkInternals& internals = *this->Internals;
  this->LastNumberOfDrawnParticles = count;
  this->LastNumberOfDrawnCells = 0;
  this->LastNumberOfDepthReads = 0;
  this->LastCullSeconds = 0.0;
  if (count <= 0)
  {
    return;
  }
  internals.BindMap(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()), program);
  this->BeginCount();
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));
  this->EndCount();
  internals.UnbindMap(program);
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Internals->Indices->ReleaseGraphicsResources();
  this->Internals->BlockTexture->ReleaseGraphicsResources(window);
  if (this->Internals->Query)
  {
    glDeleteQueries(1, &this->Internals->Query);
    this->Internals->Query = 0;
  }
  this->Internals->Context = nullptr;
  this->Internals->Cells.clear();
  this->NumberOfCells = 0;
}

//------------------------------------------------------------------------------
void vtkParticleOcclusionCuller::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ParticlesPerCell: " << this->ParticlesPerCell << "\n";
  os << indent << "MaximumNumberOfCells: " << this->MaximumNumberOfCells << "\n";
  os << indent << "BlockSize: " << this->BlockSize << "\n";
  os << indent << "DepthMargin: " << this->DepthMargin << "\n";
  os << indent << "DepthPrimed: " << this->DepthPrimed << "\n";
  os << indent << "NumberOfCells: " << this->NumberOfCells << "\n";
  os << indent << "NumberOfParticles: " << this->NumberOfParticles << "\n";
  os << indent << "LastNumberOfDrawnParticles: " << this->LastNumberOfDrawnParticles << "\n";
  os << indent << "LastNumberOfDrawnCells: " << this->LastNumberOfDrawnCells << "\n";
  os << indent << "LastNumberOfDepthReads: " << this->LastNumberOfDepthReads << "\n";
  os << indent << "LastCullSeconds: " << this->LastCullSeconds << "\n";
}
