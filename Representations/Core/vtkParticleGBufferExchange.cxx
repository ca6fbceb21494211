#include "vtkParticleGBufferExchange.h"

#include "vtkCommunicator.h"
#include "vtkFloatArray.h"
#include "vtkMultiProcessController.h"
#include "vtkObjectFactory.h"

#include <algorithm>
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
void vtkParticleGBufferExchange::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Controller: " << this->Controller.GetPointer() << "\n";
}
