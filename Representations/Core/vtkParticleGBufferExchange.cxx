#include "vtkParticleGBufferExchange.h"

#include "vtkCommunicator.h"
#include "vtkFloatArray.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h" // the OpenGL loader of this VTK
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

vtkStandardNewMacro(vtkParticleGBufferExchange);

//------------------------------------------------------------------------------
vtkParticleGBufferExchange::vtkParticleGBufferExchange() = default;

//------------------------------------------------------------------------------
vtkParticleGBufferExchange::~vtkParticleGBufferExchange() = default;

//------------------------------------------------------------------------------
void vtkParticleGBufferExchange::SetController(vtkMultiProcessController* controller)
{
  if (this->Controller != controller)
  {
    this->Controller = controller;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMultiProcessController* vtkParticleGBufferExchange::GetController()
{
  return this->Controller;
}

//------------------------------------------------------------------------------
bool vtkParticleGBufferExchange::IsDistributed()
{
  return this->Controller && this->Controller->GetNumberOfProcesses() > 1;
}

//------------------------------------------------------------------------------
void vtkParticleGBufferExchange::Sum(double* values, int n)
{
  if (!this->IsDistributed() || n < 1)
  {
    return;
  }
  std::vector<double> sent(values, values + n);
  this->Controller->AllReduce(sent.data(), values, n, vtkCommunicator::SUM_OP);
}

//------------------------------------------------------------------------------
void vtkParticleGBufferExchange::Minimum(double* values, int n)
{
  if (!this->IsDistributed() || n < 1)
  {
    return;
  }
  std::vector<double> sent(values, values + n);
  this->Controller->AllReduce(sent.data(), values, n, vtkCommunicator::MIN_OP);
}

//------------------------------------------------------------------------------
bool vtkParticleGBufferExchange::AllEqual(const double* values, int n)
{
  return vtkParticleGBufferExchange::AllEqual(
    this->IsDistributed() ? this->Controller.Get() : nullptr, values, n);
}

//------------------------------------------------------------------------------
bool vtkParticleGBufferExchange::AllEqual(
  vtkMultiProcessController* controller, const double* values, int n)
{
  if (!controller || controller->GetNumberOfProcesses() <= 1 || n < 1)
  {
    return true;
  }
  std::vector<double> sent(2 * n);
  for (int i = 0; i < n; ++i)
  {
    sent[2 * i] = values[i];
    sent[2 * i + 1] = -values[i];
  }
  std::vector<double> minima(2 * n);
  controller->AllReduce(sent.data(), minima.data(), 2 * n, vtkCommunicator::MIN_OP);
  for (int i = 0; i < n; ++i)
  {
    if (minima[2 * i] != -minima[2 * i + 1])
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleGBufferExchange::CompositeNearest(
  vtkFloatArray* depthArray, vtkFloatArray* payloadArray)
{
  if (!depthArray || !payloadArray || depthArray->GetNumberOfComponents() != 1 ||
    payloadArray->GetNumberOfTuples() != depthArray->GetNumberOfTuples())
  {
    vtkErrorMacro(<< "CompositeNearest needs a one-component depth array and a payload with as "
                     "many tuples.");
    return false;
  }
  if (!this->IsDistributed() || depthArray->GetNumberOfTuples() == 0)
  {
    return true;
  }
  const size_t n = static_cast<size_t>(depthArray->GetNumberOfTuples());
  const int components = payloadArray->GetNumberOfComponents();
  float* depth = depthArray->GetPointer(0);
  float* payload = payloadArray->GetPointer(0);
  const auto self = static_cast<std::uint64_t>(this->Controller->GetLocalProcessId());
  // 1. the nearest depth and its process: the depth's bits above the process id (a clamped,
  // non-negative float orders as its bit pattern; -0 and NaN become 0 and 1)
  std::vector<unsigned long long> keys(n);
  for (size_t i = 0; i < n; ++i)
  {
    const float d = depth[i];
    const float clamped = d > 0.0f ? std::min(d, 1.0f) : (d == d ? 0.0f : 1.0f);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &clamped, sizeof(bits));
    keys[i] = (static_cast<std::uint64_t>(bits) << 32) | self;
  }
  std::vector<unsigned long long> nearest(n);
  this->Controller->AllReduce(
    keys.data(), nearest.data(), static_cast<vtkIdType>(n), vtkCommunicator::MIN_OP);
  // 2. the owner's payload: everybody else contributes zeros
  for (size_t i = 0; i < n; ++i)
  {
    const auto bits = static_cast<std::uint32_t>(nearest[i] >> 32);
    std::memcpy(&depth[i], &bits, sizeof(bits));
    if ((nearest[i] & 0xffffffffull) != self)
    {
      std::fill_n(payload + i * components, components, 0.0f);
    }
  }
  const size_t values = n * static_cast<size_t>(components);
  std::vector<float> sent(payload, payload + values);
  this->Controller->AllReduce(
    sent.data(), payload, static_cast<vtkIdType>(values), vtkCommunicator::SUM_OP);
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticleGBufferExchange::CompositeFramebuffer(vtkOpenGLRenderWindow* context,
  vtkOpenGLFramebufferObject* framebuffer, int width, int height,
  const std::vector<vtkTarget>& targets, vtkTextureObject* depthResult, bool depthTexture)
{
  if (!context || !framebuffer || width < 1 || height < 1)
  {
    return false;
  }
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  int components = 0;
  for (const vtkTarget& target : targets)
  {
    components += target.Components;
  }
  this->Depths->SetNumberOfComponents(1);
  this->Depths->SetNumberOfTuples(static_cast<vtkIdType>(n));
  this->Payload->SetNumberOfComponents(std::max(components, 1));
  this->Payload->SetNumberOfTuples(static_cast<vtkIdType>(n));
  float* depths = this->Depths->GetPointer(0);
  float* payload = this->Payload->GetPointer(0);

  // 1. the process's own G-buffer. Every draw into it finished before it is read: on llvmpipe,
  // reading the targets right after the draws returned stale 128 x 128 blocks in about every
  // second run at np 3 (PointAO: the same frame drawn twice differed by up to 244/255); with
  // glFinish none in 12 runs. The readback stalls for the GPU anyway.
  std::vector<float> values(4 * n);
  std::vector<unsigned char> bytes(4 * n);
  vtkOpenGLState* ostate = context->GetState();
  glFinish();
  ostate->PushReadFramebufferBinding();
  framebuffer->Bind(GL_READ_FRAMEBUFFER);
  glReadPixels(0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
  int offset = 0;
  for (const vtkTarget& target : targets)
  {
    const int c = target.Components;
    const GLenum format = c == 1 ? GL_RED : GL_RGBA;
    if (target.Attachment >= 0)
    {
      framebuffer->ActivateReadBuffer(static_cast<unsigned int>(target.Attachment));
      if (target.Bytes)
      {
        glReadPixels(0, 0, width, height, format, GL_UNSIGNED_BYTE, bytes.data());
        std::copy(bytes.begin(), bytes.begin() + c * n, values.begin());
      }
      else
      {
        glReadPixels(0, 0, width, height, format, GL_FLOAT, values.data());
      }
    }
    else
    {
      std::fill(values.begin(), values.begin() + c * n, target.Fill);
    }
    for (size_t i = 0; i < n; ++i)
    {
      std::copy(
        values.begin() + c * i, values.begin() + c * (i + 1), payload + components * i + offset);
    }
    offset += target.Components;
  }
  ostate->PopReadFramebufferBinding();

  // 2. the whole picture's
  if (!this->CompositeNearest(this->Depths, this->Payload))
  {
    return false;
  }

  // 3. into the textures the pass reads
  auto upload = [&](vtkTextureObject* texture, GLenum format, GLenum type, const void* data)
  {
    texture->Activate(); // (its own texture unit, bound)
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, format, type, data);
    texture->Deactivate();
  };
  offset = 0;
  for (const vtkTarget& target : targets)
  {
    const int c = target.Components;
    const GLenum format = c == 1 ? GL_RED : GL_RGBA;
    for (size_t i = 0; i < n; ++i)
    {
      const float* p = payload + components * i + offset;
      if (target.Bytes)
      {
        for (int k = 0; k < c; ++k)
        {
          bytes[c * i + k] = static_cast<unsigned char>(std::lround(p[k]));
        }
      }
      else
      {
        std::copy(p, p + c, values.begin() + c * i);
      }
    }
    if (target.Result)
    {
      if (target.Bytes)
      {
        upload(target.Result, format, GL_UNSIGNED_BYTE, bytes.data());
      }
      else
      {
        upload(target.Result, format, GL_FLOAT, values.data());
      }
    }
    offset += target.Components;
  }
  if (depthResult)
  {
    upload(depthResult, depthTexture ? GL_DEPTH_COMPONENT : GL_RED, GL_FLOAT, depths);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkParticleGBufferExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller.GetPointer() << "\n";
}
