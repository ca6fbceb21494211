#include "vtkParticlePassChain.h"

#include "vtkImageProcessingPass.h"
#include "vtkObjectFactory.h"
#include "vtkRenderState.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <vector>

class vtkParticlePassChain::vtkInternals
{
public:
  std::vector<vtkSmartPointer<vtkImageProcessingPass>> Passes;
};

vtkStandardNewMacro(vtkParticlePassChain);

//------------------------------------------------------------------------------
vtkParticlePassChain::vtkParticlePassChain()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticlePassChain::~vtkParticlePassChain()
{
  this->RemoveAllPasses();
  this->SetInnerPass(nullptr);
  delete this->Internals;
}

//------------------------------------------------------------------------------
void vtkParticlePassChain::SetInnerPass(vtkRenderPass* pass)
{
  if (this->InnerPass == pass)
  {
    return;
  }
  vtkRenderPass* old = this->InnerPass;
  this->InnerPass = pass;
  if (pass)
  {
    pass->Register(this);
  }
  this->WarnedNoInnerPass = false;
  this->LinkPasses();
  if (old)
  {
    old->UnRegister(this);
  }
  this->Modified();
}

//------------------------------------------------------------------------------
bool vtkParticlePassChain::AddPass(vtkImageProcessingPass* pass)
{
  return this->InsertPass(this->GetNumberOfPasses(), pass);
}

//------------------------------------------------------------------------------
bool vtkParticlePassChain::InsertPass(int index, vtkImageProcessingPass* pass)
{
  if (!pass)
  {
    vtkErrorMacro(<< "Cannot add a null pass.");
    return false;
  }
  if (this->HasPass(pass))
  {
    vtkErrorMacro(<< "The " << pass->GetClassName() << " is already in the chain.");
    return false;
  }
  auto& passes = this->Internals->Passes;
  index = std::max(0, std::min(index, static_cast<int>(passes.size())));
  passes.insert(passes.begin() + index, pass);
  this->LinkPasses();
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkParticlePassChain::RemovePass(vtkImageProcessingPass* pass)
{
  auto& passes = this->Internals->Passes;
  auto it = std::find(passes.begin(), passes.end(), pass);
  if (it == passes.end())
  {
    return false;
  }
  vtkSmartPointer<vtkImageProcessingPass> removed = *it;
  passes.erase(it);
  removed->SetDelegatePass(nullptr);
  this->LinkPasses();
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
void vtkParticlePassChain::RemoveAllPasses()
{
  auto& passes = this->Internals->Passes;
  if (passes.empty())
  {
    return;
  }
  for (auto& pass : passes)
  {
    pass->SetDelegatePass(nullptr);
  }
  passes.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkParticlePassChain::GetNumberOfPasses() const
{
  return static_cast<int>(this->Internals->Passes.size());
}

//------------------------------------------------------------------------------
vtkImageProcessingPass* vtkParticlePassChain::GetPass(int index) const
{
  const auto& passes = this->Internals->Passes;
  if (index < 0 || index >= static_cast<int>(passes.size()))
  {
    return nullptr;
  }
  return passes[index];
}

//------------------------------------------------------------------------------
bool vtkParticlePassChain::HasPass(vtkImageProcessingPass* pass) const
{
  const auto& passes = this->Internals->Passes;
  return pass && std::find(passes.begin(), passes.end(), pass) != passes.end();
}

//------------------------------------------------------------------------------
void vtkParticlePassChain::LinkPasses()
{
  auto& passes = this->Internals->Passes;
  for (size_t i = 0; i < passes.size(); ++i)
  {
    vtkRenderPass* next =
      i + 1 < passes.size() ? static_cast<vtkRenderPass*>(passes[i + 1].Get()) : this->InnerPass;
    if (passes[i]->GetDelegatePass() != next)
    {
      passes[i]->SetDelegatePass(next);
    }
  }
}

//------------------------------------------------------------------------------
void vtkParticlePassChain::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  if (!this->InnerPass)
  {
    if (!this->WarnedNoInnerPass)
    {
      vtkWarningMacro(<< "No InnerPass: the chain renders nothing.");
      this->WarnedNoInnerPass = true;
    }
    return;
  }
  this->LinkPasses();
  auto& passes = this->Internals->Passes;
  vtkRenderPass* outermost =
    passes.empty() ? this->InnerPass : static_cast<vtkRenderPass*>(passes.front().Get());
  outermost->Render(s);
  this->NumberOfRenderedProps = outermost->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkParticlePassChain::ReleaseGraphicsResources(vtkWindow* window)
{
  for (auto& pass : this->Internals->Passes)
  {
    pass->ReleaseGraphicsResources(window);
  }
  if (this->InnerPass)
  {
    this->InnerPass->ReleaseGraphicsResources(window);
  }
}

//------------------------------------------------------------------------------
void vtkParticlePassChain::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InnerPass: ";
  if (this->InnerPass)
  {
    os << this->InnerPass->GetClassName() << " (" << this->InnerPass << ")\n";
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "NumberOfPasses: " << this->GetNumberOfPasses() << "\n";
  int i = 0;
  for (auto& pass : this->Internals->Passes)
  {
    os << indent << "Pass " << i++ << ": " << pass->GetClassName() << " (" << pass.Get() << ")\n";
  }
}
