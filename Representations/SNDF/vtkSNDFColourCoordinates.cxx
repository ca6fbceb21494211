#include "vtkSNDFColourCoordinates.h"

#include "vtkActor.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkMapper.h"
#include "vtkObject.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkSMPTools.h"
#include "vtkScalarsToColors.h"
#include "vtkSetGet.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"

#include "vtkParticleCompat.h"

#include <algorithm>
#include <cmath>
#include <set>

//------------------------------------------------------------------------------
void vtkSNDFColourCoordinates::Place(std::size_t a, std::size_t count, float& offset, float& scale)
{
  const double k = static_cast<double>(count);
  offset = static_cast<float>((a + Margin(count)) / k);
  scale = static_cast<float>((1.0 - 2.0 * Margin(count)) / k);
}

//------------------------------------------------------------------------------
bool vtkSNDFColourCoordinates::UsesScalarColours(vtkMapper* mapper)
{
  if (!mapper->GetScalarVisibility())
  {
    return false;
  }
  vtkDataSet* input = vtkDataSet::SafeDownCast(mapper->GetInputDataObject(0, 0));
  int cellFlag = 0;
  return !input ||
    vtkAbstractMapper::GetScalars(input, mapper->GetScalarMode(), mapper->GetArrayAccessMode(),
      mapper->GetArrayId(), mapper->GetArrayName(), cellFlag) != nullptr;
}

//------------------------------------------------------------------------------
vtkUnsignedCharArray* vtkSNDFColourCoordinates::MappedColours(vtkActor* actor)
{
  vtkMapper* mapper = actor->GetMapper();
  return UsesScalarColours(mapper) ? mapper->MapScalars(1.0) : nullptr;
}

//------------------------------------------------------------------------------
bool vtkSNDFColourCoordinates::FindSource(
  vtkActor* actor, vtkDataArray*& array, vtkScalarsToColors*& table, int& component)
{
  vtkMapper* mapper = actor->GetMapper();
  vtkDataSet* input = mapper ? vtkDataSet::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  if (!input || !UsesScalarColours(mapper))
  {
    return false;
  }
  table = mapper->GetLookupTable();
  int cellFlag = 0;
  array = vtkAbstractMapper::GetScalars(input, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  if (!table || !array || cellFlag != 0 || array->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    return false;
  }
  const int mode = mapper->GetColorMode();
  if (mode == VTK_COLOR_MODE_DIRECT_SCALARS ||
    (mode == VTK_COLOR_MODE_DEFAULT && vtkUnsignedCharArray::SafeDownCast(array)))
  {
    return false;
  }
  const int n = array->GetNumberOfComponents();
  component = 0;
  if (n > 1)
  {
    if (table->GetVectorMode() == vtkScalarsToColors::COMPONENT)
    {
      component = std::min(std::max(table->GetVectorComponent(), 0), n - 1);
    }
    else if (table->GetVectorMode() == vtkScalarsToColors::MAGNITUDE &&
      table->GetVectorComponent() == 0 &&
      (table->GetVectorSize() == -1 || table->GetVectorSize() >= n))
    {
      component = -1;
    }
    else
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFColourCoordinates::CanKeep(const std::vector<vtkActor*>& particles)
{
  if (particles.empty() || particles.size() > MaximumActors)
  {
    return false;
  }
  bool table = false;
  for (vtkActor* actor : particles)
  {
    vtkDataArray* array = nullptr;
    vtkScalarsToColors* lut = nullptr;
    int component = 0;
    if (FindSource(actor, array, lut, component))
    {
      table = true;
    }
    else if (UsesScalarColours(actor->GetMapper()))
    {
      return false; // direct colours, cell scalars, RGB vector mode
    }
  }
  return table;
}

//------------------------------------------------------------------------------
double vtkSNDFColourCoordinates::Value(
  vtkDataArray* array, vtkIdType i, int component, double* tuple)
{
  if (component >= 0)
  {
    return array->GetComponent(i, component);
  }
  array->GetTuple(i, tuple);
  double sum = 0.0;
  for (int c = 0; c < array->GetNumberOfComponents(); ++c)
  {
    sum += tuple[c] * tuple[c];
  }
  return std::sqrt(sum);
}

//------------------------------------------------------------------------------
bool vtkSNDFColourCoordinates::Normalise(
  vtkDataArray* array, int component, double range[2], std::vector<float>& t)
{
  const vtkIdType n = array->GetNumberOfTuples();
  const int comps = array->GetNumberOfComponents();
  std::vector<double> values(static_cast<std::size_t>(n));
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<double> tuple(static_cast<std::size_t>(comps));
      for (vtkIdType i = begin; i < end; ++i)
      {
        values[i] = Value(array, i, component, tuple.data());
      }
    });
  double lo = VTK_DOUBLE_MAX;
  double hi = -VTK_DOUBLE_MAX;
  for (double v : values)
  {
    if (!std::isfinite(v))
    {
      return false;
    }
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  range[0] = lo;
  range[1] = hi;
  t.resize(values.size());
  const double scale = hi > lo ? 1.0 / (hi - lo) : 0.0;
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        t[i] = static_cast<float>(std::min(1.0, std::max(0.0, (values[i] - lo) * scale)));
      }
    });
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFColourCoordinates::FindCategories(Actor& c)
{
  if (!c.HaveCategories && c.Array)
  {
    c.HaveCategories = true;
    std::set<double> seen;
    const int comps = c.Array->GetNumberOfComponents();
    std::vector<double> tuple(static_cast<std::size_t>(comps));
    for (vtkIdType i = 0; i < c.Array->GetNumberOfTuples() && seen.size() <= 4096; ++i)
    {
      seen.insert(Value(c.Array, i, c.Component, tuple.data()));
    }
    if (seen.size() <= 4096)
    {
      c.Categories.assign(seen.begin(), seen.end());
    }
  }
  return !c.Categories.empty();
}

//------------------------------------------------------------------------------
double vtkSNDFColourCoordinates::NearestCategory(const std::vector<double>& categories, double v)
{
  auto above = std::lower_bound(categories.begin(), categories.end(), v);
  if (above == categories.end() || (above != categories.begin() && v - *(above - 1) < *above - v))
  {
    --above;
  }
  return *above;
}

//------------------------------------------------------------------------------
bool vtkSNDFColourCoordinates::Update(const std::vector<vtkActor*>& particles,
  vtkOpenGLRenderWindow* context, vtkObject* owner,
  const std::function<bool(const std::string&)>& firstWarning)
{
  this->Actors.resize(particles.size());
  this->Props.assign(particles.begin(), particles.end());
  bool solid = false;
  for (std::size_t a = 0; a < particles.size(); ++a)
  {
    if (!this->UpdateActor(this->Actors[a], particles[a], context, owner, firstWarning))
    {
      return false;
    }
    solid = solid || this->Actors[a].Solid;
  }
  if (solid && !this->SolidTexture)
  {
    this->SolidBuffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->SolidTexture = vtkSmartPointer<vtkTextureObject>::New();
    this->SolidTexture->SetContext(context);
    const std::vector<float> zero(1, 0.0f);
    if (!this->SolidBuffer->Upload(zero, vtkOpenGLBufferObject::TextureBuffer) ||
      !this->SolidTexture->CreateTextureBuffer(1, 1, VTK_FLOAT, this->SolidBuffer))
    {
      this->SolidTexture = nullptr;
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkSNDFColourCoordinates::UpdateActor(Actor& c, vtkActor* actor,
  vtkOpenGLRenderWindow* context, vtkObject* owner,
  const std::function<bool(const std::string&)>& firstWarning)
{
  vtkDataArray* array = nullptr;
  vtkScalarsToColors* table = nullptr;
  int component = 0;
  if (!FindSource(actor, array, table, component))
  {
    c.Solid = true; // (CanKeep: the property's colour)
    c.Valid = true;
    return true;
  }
  if (!c.Solid && c.Array == array && c.Time == array->GetMTime() && c.Component == component)
  {
    return c.Valid;
  }
  c.Solid = false;
  c.Valid = false;
  c.Array = array;
  c.Time = array->GetMTime();
  c.Component = component;
  c.HaveCategories = false;
  c.Categories.clear();
  const vtkIdType n = array->GetNumberOfTuples();
  GLint limit = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &limit);
  if (n < 1 || n > static_cast<vtkIdType>(limit))
  {
    if (n > 0 && firstWarning("coordinates " + std::to_string(n)))
    {
      vtkWarningWithObjectMacro(owner, << n << " particles exceed the context's texture buffer "
                                       << "size (" << limit << "): a new colour map samples "
                                       << "again unless its colours are linear in the old ones.");
    }
    return false;
  }
  std::vector<float> t;
  if (!Normalise(array, component, c.Range, t))
  {
    return false;
  }
  if (!c.Buffer)
  {
    c.Buffer = vtkSmartPointer<vtkOpenGLBufferObject>::New();
  }
  if (c.Texture)
  {
    c.Texture->ReleaseGraphicsResources(context);
  }
  c.Texture = vtkSmartPointer<vtkTextureObject>::New();
  c.Texture->SetContext(context);
  c.Valid = c.Buffer->Upload(t, vtkOpenGLBufferObject::TextureBuffer) &&
    c.Texture->CreateTextureBuffer(static_cast<unsigned int>(n), 1, VTK_FLOAT, c.Buffer);
  return c.Valid;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkSNDFColourCoordinates::Source(
  vtkProp* prop, float& offset, float& scale, int& solid) const
{
  const auto found = std::find(this->Props.begin(), this->Props.end(), prop);
  if (found == this->Props.end() || this->Actors.size() != this->Props.size())
  {
    return nullptr;
  }
  const std::size_t a = static_cast<std::size_t>(found - this->Props.begin());
  Place(a, this->Actors.size(), offset, scale);
  solid = this->Actors[a].Solid ? 1 : 0;
  return solid ? this->SolidTexture.Get() : this->Actors[a].Texture.Get();
}

//------------------------------------------------------------------------------
std::vector<float> vtkSNDFColourCoordinates::MakeRamp(
  const std::vector<vtkScalarsToColors*>& tables, const std::vector<SampledColours>& stored)
{
  const int k = static_cast<int>(this->Actors.size());
  if (k < 1 || tables.size() != this->Actors.size() || stored.size() != tables.size())
  {
    return std::vector<float>();
  }
  for (int a = 0; a < k; ++a)
  {
    if (!this->Actors[a].Solid && tables[a]->GetIndexedLookup() && !FindCategories(this->Actors[a]))
    {
      return std::vector<float>();
    }
  }
  const int size = RampPerActor * k;
  const double margin = this->Margin();
  std::vector<float> ramp(4 * static_cast<std::size_t>(size));
  for (int i = 0; i < size; ++i)
  {
    const double global = k * (i / (size - 1.0));
    const int a = std::min(k - 1, static_cast<int>(global));
    const double local = std::min(1.0, std::max(0.0, (global - a - margin) / (1.0 - 2.0 * margin)));
    const Actor& c = this->Actors[a];
    float* entry = &ramp[4 * static_cast<std::size_t>(i)];
    if (c.Solid)
    {
      for (int j = 0; j < 3; ++j)
      {
        entry[j] = static_cast<float>(stored[a].Solid[j]);
      }
      entry[3] = 1.0f;
      continue;
    }
    vtkScalarsToColors* table = tables[a];
    double v = c.Range[0] + (c.Range[1] - c.Range[0]) * local;
    if (table->GetIndexedLookup())
    {
      v = NearestCategory(c.Categories, v);
    }
    const unsigned char* rgba = table->MapValue(v);
    for (int j = 0; j < 3; ++j)
    {
      entry[j] = static_cast<float>(stored[a].Scale * rgba[j] / 255.0);
    }
    entry[3] = static_cast<float>(rgba[3] / 255.0);
  }
  return ramp;
}

//------------------------------------------------------------------------------
std::vector<float> vtkSNDFColourCoordinates::MakeRamp(
  const std::vector<vtkActor*>& particles, const std::vector<SampledColours>& stored)
{
  if (particles.size() != this->Actors.size())
  {
    return std::vector<float>();
  }
  std::vector<vtkScalarsToColors*> tables(particles.size(), nullptr);
  for (std::size_t a = 0; a < particles.size(); ++a)
  {
    if (!this->Actors[a].Solid)
    {
      tables[a] = particles[a]->GetMapper()->GetLookupTable();
    }
  }
  return this->MakeRamp(tables, stored);
}

//------------------------------------------------------------------------------
void vtkSNDFColourCoordinates::Deactivate()
{
  for (Actor& c : this->Actors)
  {
    if (c.Texture)
    {
      c.Texture->Deactivate();
    }
  }
  if (this->SolidTexture)
  {
    this->SolidTexture->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkSNDFColourCoordinates::Release(vtkWindow* w)
{
  for (Actor& c : this->Actors)
  {
    if (c.Texture)
    {
      c.Texture->ReleaseGraphicsResources(w);
    }
    if (c.Buffer)
    {
      c.Buffer->ReleaseGraphicsResources();
    }
  }
  this->Actors.clear();
  this->Props.clear();
  this->Ramp.clear();
  if (this->SolidTexture)
  {
    this->SolidTexture->ReleaseGraphicsResources(w);
  }
  this->SolidTexture = nullptr;
  if (this->SolidBuffer)
  {
    this->SolidBuffer->ReleaseGraphicsResources();
  }
  this->SolidBuffer = nullptr;
}
