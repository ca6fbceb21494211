#include "vtkSNDFRecolouring.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProperty.h"
#include "vtkSNDFTileCache.h"
#include "vtkScalarsToColors.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

//------------------------------------------------------------------------------
bool vtkSNDFRecolouring::FitColourMatrix(
  const std::vector<Pair>& pairs, double m[3][3], double tolerance)
{
  double g[3][3] = { { 0.0 } };
  double b[3][3] = { { 0.0 } };
  for (const auto& pair : pairs)
  {
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        g[i][j] += pair[i] * pair[j];
        b[i][j] += pair[i] * pair[3 + j];
      }
    }
  }
  double eigenvalues[3];
  double vectors[3][3];
  double* gRows[3] = { g[0], g[1], g[2] };
  double* vRows[3] = { vectors[0], vectors[1], vectors[2] };
  vtkMath::Jacobi(gRows, eigenvalues, vRows); // (eigenvalues decreasing, vectors in columns)
  double inverse[3][3] = { { 0.0 } };
  for (int k = 0; k < 3; ++k)
  {
    if (eigenvalues[k] <= 1e-10 * std::max(eigenvalues[0], 1e-300))
    {
      continue;
    }
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        inverse[i][j] += vectors[i][k] * vectors[j][k] / eigenvalues[k];
      }
    }
  }
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      // M^T = G^+ B
      m[row][column] = 0.0;
      for (int k = 0; k < 3; ++k)
      {
        m[row][column] += inverse[column][k] * b[k][row];
      }
      if (!(std::abs(m[row][column]) <= 16.0))
      {
        return false;
      }
    }
  }
  for (const auto& pair : pairs)
  {
    for (int row = 0; row < 3; ++row)
    {
      const double mapped = m[row][0] * pair[0] + m[row][1] * pair[1] + m[row][2] * pair[2];
      if (!(std::abs(mapped - pair[3 + row]) <= tolerance))
      {
        return false;
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSNDFRecolouring::SampledColours vtkSNDFRecolouring::StoredColours(
  vtkActor* actor, int rawMaterial)
{
  SampledColours stored;
  stored.Colours = vtkSNDFColourCoordinates::MappedColours(actor);
  stored.Time = stored.Colours ? stored.Colours->GetMTime() : 0;
  vtkProperty* p = actor->GetProperty();
  stored.Scale = rawMaterial == 1 ? 1.0 : p->GetDiffuse();
  for (int c = 0; c < 3; ++c)
  {
    stored.Solid[c] = stored.Scale * p->GetDiffuseColor()[c];
  }
  return stored;
}

//------------------------------------------------------------------------------
bool vtkSNDFRecolouring::AddPairs(const SampledColours& then, const SampledColours& now,
  double ambient, bool coloured, bool& changed, std::vector<Pair>& pairs)
{
  if (!now.Colours && !then.Colours)
  {
    // the property's colour: one pair (its ambient term is the ambient colour's)
    if (!std::equal(now.Solid, now.Solid + 3, then.Solid))
    {
      if (coloured)
      {
        return false;
      }
      changed = true;
    }
    pairs.push_back(
      { then.Solid[0], then.Solid[1], then.Solid[2], now.Solid[0], now.Solid[1], now.Solid[2] });
    return true;
  }
  if (!now.Colours || !then.Colours || now.Colours->GetNumberOfComponents() != 4 ||
    then.Colours->GetNumberOfComponents() != 4 ||
    now.Colours->GetNumberOfTuples() != then.Colours->GetNumberOfTuples())
  {
    return false;
  }
  if (now.Colours == then.Colours && now.Time != then.Time)
  {
    return false; // mapped anew into the same array: the old colours are gone
  }
  if (now.Colours != then.Colours || now.Scale != then.Scale)
  {
    if (ambient != 0.0 || coloured)
    {
      return false; // colour-dependent light in the colour target, which keeps no bins
    }
    changed = true;
  }
  std::unordered_map<std::uint32_t, std::uint32_t> seen;
  const unsigned char* o = then.Colours->GetPointer(0);
  const unsigned char* n = now.Colours->GetPointer(0);
  const vtkIdType count = now.Colours->GetNumberOfTuples();
  for (vtkIdType i = 0; i < count; ++i, o += 4, n += 4)
  {
    if (o[3] != n[3])
    {
      return false; // the opacity changed too
    }
    const std::uint32_t key = o[0] | (o[1] << 8) | (o[2] << 16);
    const std::uint32_t value = n[0] | (n[1] << 8) | (n[2] << 16);
    const auto found = seen.emplace(key, value);
    if (!found.second && found.first->second != value)
    {
      return false; // one old colour, two new ones: not a function of the colour
    }
    if (found.second && seen.size() > 4096)
    {
      return false; // a continuous map: not worth the fit
    }
  }
  for (const auto& pair : seen)
  {
    Pair entry;
    for (int c = 0; c < 3; ++c)
    {
      entry[c] = then.Scale / 255.0 * ((pair.first >> (8 * c)) & 0xFFu);
      entry[3 + c] = now.Scale / 255.0 * ((pair.second >> (8 * c)) & 0xFFu);
    }
    pairs.push_back(entry);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkSNDFRecolouring::RampResidual(
  const std::vector<float>& oldRamp, const std::vector<float>& newRamp, double residual[3][3])
{
  const std::size_t size = newRamp.size() / 4;
  double centre[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < size; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      centre[k] += oldRamp[4 * i + k] / static_cast<double>(size);
      centre[3 + k] += newRamp[4 * i + k] / static_cast<double>(size);
    }
  }
  std::vector<Pair> pairs(size);
  for (std::size_t i = 0; i < size; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      pairs[i][k] = oldRamp[4 * i + k] - centre[k];
      pairs[i][3 + k] = newRamp[4 * i + k] - centre[3 + k];
    }
  }
  if (!FitColourMatrix(pairs, residual, std::numeric_limits<double>::infinity()))
  {
    std::fill(&residual[0][0], &residual[0][0] + 9, 0.0);
  }
}

//------------------------------------------------------------------------------
void vtkSNDFRecolouring::KeepColours(const std::vector<vtkActor*>& particles, int rawMaterial)
{
  this->Colours.clear();
  for (vtkActor* actor : particles)
  {
    this->Colours.push_back(StoredColours(actor, rawMaterial));
  }
  this->Coordinates->Ramp.clear();
  if (this->Coordinates->InShader)
  {
    this->Coordinates->Ramp = this->Coordinates->MakeRamp(particles, this->Colours);
  }
}

//------------------------------------------------------------------------------
int vtkSNDFRecolouring::Recolour(const std::vector<vtkActor*>& particles, bool coloured,
  int rawMaterial, vtkOpenGLRenderWindow* context)
{
  const int linear = this->RecolourLinear(particles, coloured, rawMaterial);
  return linear >= 0 ? linear : this->RecolourMap(particles, coloured, rawMaterial, context);
}

//------------------------------------------------------------------------------
int vtkSNDFRecolouring::RecolourLinear(
  const std::vector<vtkActor*>& particles, bool coloured, int rawMaterial)
{
  if (particles.size() != this->Colours.size())
  {
    return -1;
  }
  std::vector<Pair> pairs;
  bool changed = false;
  for (std::size_t a = 0; a < particles.size(); ++a)
  {
    const SampledColours now = StoredColours(particles[a], rawMaterial);
    if (!AddPairs(this->Colours[a], now, particles[a]->GetProperty()->GetAmbient(), coloured,
          changed, pairs))
    {
      return -1;
    }
  }
  if (!changed)
  {
    return 0;
  }
  double matrix[3][3];
  if (!FitColourMatrix(pairs, matrix, 0.05 / 255.0))
  {
    return -1;
  }
  this->Cache->Recolour(matrix);
  this->KeepColours(particles, rawMaterial);
  return 1;
}

//------------------------------------------------------------------------------
int vtkSNDFRecolouring::RecolourMap(const std::vector<vtkActor*>& particles, bool coloured,
  int rawMaterial, vtkOpenGLRenderWindow* context)
{
  vtkSNDFColourCoordinates& coordinates = *this->Coordinates;
  if (!this->Cache->GetMoments() || !coordinates.InShader || coordinates.Ramp.empty() || coloured ||
    particles.size() != coordinates.Actors.size() ||
    !std::equal(particles.begin(), particles.end(), coordinates.Props.begin()))
  {
    return -1;
  }
  std::vector<SampledColours> now;
  for (std::size_t a = 0; a < particles.size(); ++a)
  {
    const vtkSNDFColourCoordinates::Actor& c = coordinates.Actors[a];
    vtkDataArray* array = nullptr;
    vtkScalarsToColors* table = nullptr;
    int component = 0;
    const bool source = vtkSNDFColourCoordinates::FindSource(particles[a], array, table, component);
    if (!c.Valid || source == c.Solid)
    {
      return -1;
    }
    if (!c.Solid &&
      (array != c.Array || array->GetMTime() != c.Time || component != c.Component ||
        particles[a]->GetProperty()->GetAmbient() != 0.0))
    {
      return -1;
    }
    now.push_back(StoredColours(particles[a], rawMaterial)); // (maps: the table's range)
    if (!c.Solid && !now.back().Colours)
    {
      return -1;
    }
  }
  const std::vector<float> ramp = coordinates.MakeRamp(particles, now);
  if (ramp.empty() || ramp.size() != coordinates.Ramp.size())
  {
    return -1; // an indexed table with more than 4096 values
  }
  const std::size_t size = ramp.size() / 4;
  for (std::size_t i = 0; i < size; ++i)
  {
    if (ramp[4 * i + 3] != coordinates.Ramp[4 * i + 3])
    {
      return -1; // the opacities changed
    }
  }
  std::vector<float> ramps = coordinates.Ramp;
  ramps.insert(ramps.end(), ramp.begin(), ramp.end());
  // the old maps' quadrature error of a bin carried into the new maps
  double residual[3][3];
  RampResidual(coordinates.Ramp, ramp, residual);
  if (!this->Ramps)
  {
    this->Ramps = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->Ramps->SetContext(context);
  const int width = static_cast<int>(size);
  if (!this->Ramps->Create2DFromRaw(width, 2, 4, VTK_FLOAT, ramps.data()) ||
    this->Cache->RecolourMap(this->Ramps, width, residual) <= 0)
  {
    return -1;
  }
  this->KeepColours(particles, rawMaterial);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSNDFRecolouring::Release(vtkWindow* w)
{
  if (this->Ramps)
  {
    this->Ramps->ReleaseGraphicsResources(w);
  }
  this->Ramps = nullptr;
}
