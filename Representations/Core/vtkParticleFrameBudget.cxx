#include "vtkParticleFrameBudget.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderTimer.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <sstream>
#include <vector>

namespace
{
// a frame's timer and the level it timed
struct PendingTimer
{
  int Level = 0;
  std::unique_ptr<vtkOpenGLRenderTimer> Timer;
};

// at most this many frames wait for their timer results (a GPU runs a few frames behind)
constexpr std::size_t MaximumPendingTimers = 4;

std::vector<std::string> SplitNames(const std::string& names)
{
  std::vector<std::string> result;
  std::stringstream stream(names);
  std::string name;
  while (std::getline(stream, name, '|'))
  {
    result.push_back(name);
  }
  return result;
}

std::string FormatMilliseconds(double seconds)
{
  if (!std::isfinite(seconds))
  {
    return "unlimited";
  }
  std::ostringstream text;
  text.precision(seconds < 0.01 ? 2 : 3);
  text << seconds * 1e3 << " ms";
  return text.str();
}
}

class vtkParticleFrameBudget::vtkInternals
{
public:
  std::vector<double> Times; // per level; -1: never measured
  std::deque<PendingTimer> Pending;
  bool Timing = false;
};

vtkStandardNewMacro(vtkParticleFrameBudget);

//------------------------------------------------------------------------------
vtkParticleFrameBudget::vtkParticleFrameBudget()
  : Internals(new vtkInternals)
{
}

//------------------------------------------------------------------------------
vtkParticleFrameBudget::~vtkParticleFrameBudget() = default;

//------------------------------------------------------------------------------
double vtkParticleFrameBudget::GetFrameTime(vtkRenderer* ren)
{
  vtkRenderWindow* window = ren ? ren->GetRenderWindow() : nullptr;
  const double rate = window ? window->GetDesiredUpdateRate() : 0.0;
  return rate > 0.0 ? 1.0 / rate : std::numeric_limits<double>::infinity();
}

//------------------------------------------------------------------------------
int vtkParticleFrameBudget::ChooseLevel(double frameTime, int numberOfLevels)
{
  const int exact = std::max(numberOfLevels, 1) - 1;
  int level = exact;
  if (this->Quality == INTERACTIVE)
  {
    level = 0;
  }
  else if (this->Quality == ADAPTIVE && !(frameTime >= this->StillFrameTime) && !this->ChooseByTime)
  {
    level = 0;
  }
  else if (this->Quality == ADAPTIVE && !(frameTime >= this->StillFrameTime))
  {
    level = -1;
    for (int l = exact; l >= 0 && level < 0; --l)
    {
      const double measured = this->GetMeasuredTime(l);
      level = measured >= 0.0 && measured <= frameTime ? l : -1;
    }
    if (level < 0 && this->GetMeasuredTime(0) >= 0.0)
    {
      // nothing fits: the fastest level measured (a "cheap" level need not be cheaper on every
      // scene), the more accurate one of equal times
      level = exact;
      for (int l = exact - 1; l >= 0; --l)
      {
        const double measured = this->GetMeasuredTime(l);
        const double best = this->GetMeasuredTime(level);
        level = measured >= 0.0 && (best < 0.0 || measured < best) ? l : level;
      }
    }
    level = std::max(level, 0); // the cheapest, not measured yet, is tried
    if (level + 1 < exact && this->GetMeasuredTime(level) >= 0.0 &&
      this->GetMeasuredTime(level) <= frameTime && this->GetMeasuredTime(level + 1) < 0.0)
    {
      ++level; // the next level between, not measured yet, is tried once when this one fits
    }
  }
  this->LastLevel = level;
  this->LastNumberOfLevels = exact + 1;
  this->LastFrameTime = frameTime;
  return level;
}

//------------------------------------------------------------------------------
void vtkParticleFrameBudget::ReportTime(int level, double seconds)
{
  if (level < 0 || !(seconds >= 0.0) || !std::isfinite(seconds))
  {
    return;
  }
  std::vector<double>& times = this->Internals->Times;
  if (static_cast<std::size_t>(level) >= times.size())
  {
    times.resize(static_cast<std::size_t>(level) + 1, -1.0);
  }
  double& estimate = times[static_cast<std::size_t>(level)];
  // a faster time is taken as it is (the slow outliers are the frames that compile shaders or
  // build volumes); a slower one moves the estimate half way
  estimate = estimate < 0.0 || seconds < estimate ? seconds : 0.5 * (estimate + seconds);
}

//------------------------------------------------------------------------------
double vtkParticleFrameBudget::GetMeasuredTime(int level)
{
  const std::vector<double>& times = this->Internals->Times;
  return level >= 0 && static_cast<std::size_t>(level) < times.size()
    ? times[static_cast<std::size_t>(level)]
    : -1.0;
}

//------------------------------------------------------------------------------
void vtkParticleFrameBudget::ForgetTimes()
{
  this->Internals->Times.clear();
}

//------------------------------------------------------------------------------
void vtkParticleFrameBudget::ReadFinishedTimers()
{
  std::deque<PendingTimer>& pending = this->Internals->Pending;
  while (!pending.empty() && pending.front().Timer->Ready())
  {
    this->ReportTime(pending.front().Level, pending.front().Timer->GetElapsedSeconds());
    pending.front().Timer->ReleaseGraphicsResources();
    pending.pop_front();
  }
  while (pending.size() >= MaximumPendingTimers)
  {
    pending.front().Timer->ReleaseGraphicsResources();
    pending.pop_front();
  }
}

//------------------------------------------------------------------------------
int vtkParticleFrameBudget::ChooseFrameLevel(vtkRenderer* ren, int numberOfLevels)
{
  this->EndFrame();
  if (vtkOpenGLRenderTimer::IsSupported())
  {
    this->ReadFinishedTimers();
  }
  return this->ChooseLevel(GetFrameTime(ren), numberOfLevels);
}

//------------------------------------------------------------------------------
int vtkParticleFrameBudget::BeginFrame(vtkRenderer* ren, int numberOfLevels)
{
  const int level = this->ChooseFrameLevel(ren, numberOfLevels);
  this->StartTiming();
  return level;
}

//------------------------------------------------------------------------------
void vtkParticleFrameBudget::StartTiming()
{
  this->EndFrame();
  if (!vtkOpenGLRenderTimer::IsSupported())
  {
    return;
  }
  this->ReadFinishedTimers();
  PendingTimer timer;
  timer.Level = this->LastLevel;
  timer.Timer.reset(new vtkOpenGLRenderTimer);
  timer.Timer->Start();
  this->Internals->Pending.push_back(std::move(timer));
  this->Internals->Timing = true;
}

//------------------------------------------------------------------------------
void vtkParticleFrameBudget::EndFrame()
{
  if (this->Internals->Timing && !this->Internals->Pending.empty())
  {
    this->Internals->Pending.back().Timer->Stop();
  }
  this->Internals->Timing = false;
}

//------------------------------------------------------------------------------
std::string vtkParticleFrameBudget::GetLastChoiceText(const std::string& levelNames)
{
  const std::vector<std::string> names = SplitNames(levelNames);
  const int exact = this->LastNumberOfLevels - 1;
  auto name = [&](int level)
  {
    return static_cast<std::size_t>(level) < names.size() ? names[level]
                                                          : "level " + std::to_string(level);
  };
  std::ostringstream text;
  text << name(this->LastLevel);
  if (this->Quality == EXACT)
  {
    text << " (exact quality asked for)";
  }
  else if (this->Quality == INTERACTIVE)
  {
    text << " (interactive quality asked for)";
  }
  else if (!this->GetLastFrameInteractive())
  {
    text << " (still frame)";
  }
  else
  {
    text << " (interactive frame of " << FormatMilliseconds(this->LastFrameTime)
         << (this->ChooseByTime ? ")" : ", the cheapest level on every process)");
  }
  if (exact > 0)
  {
    text << "; measured:";
    for (int level = 0; level <= exact; ++level)
    {
      const double t = this->GetMeasuredTime(level);
      text << (level ? ", " : " ") << name(level) << " "
           << (t < 0.0 ? std::string("not yet") : FormatMilliseconds(t));
    }
  }
  return text.str();
}

//------------------------------------------------------------------------------
void vtkParticleFrameBudget::ReleaseGraphicsResources(vtkWindow*)
{
  for (PendingTimer& timer : this->Internals->Pending)
  {
    timer.Timer->ReleaseGraphicsResources();
  }
  this->Internals->Pending.clear();
  this->Internals->Timing = false;
}

//------------------------------------------------------------------------------
void vtkParticleFrameBudget::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Quality: " << this->Quality << "\n";
  os << indent << "ChooseByTime: " << this->ChooseByTime << "\n";
  os << indent << "StillFrameTime: " << this->StillFrameTime << "\n";
  os << indent << "LastLevel: " << this->LastLevel << " of " << this->LastNumberOfLevels << "\n";
  os << indent << "LastFrameTime: " << this->LastFrameTime << "\n";
}
