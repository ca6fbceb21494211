// TestParticleFrameBudget: vtkParticleFrameBudget's choice of a quality level (no OpenGL):
//   a) still frames (at least StillFrameTime) draw the exact level whatever it costs;
//   b) an interactive frame draws the most accurate measured level that fits; when none fits,
//      the cheapest once (to measure it), then the fastest measured (the more accurate of equal
//      times); never an unmeasured expensive one;
//   c) the budget is honoured in direction: a longer frame never picks a cheaper level;
//   d) EXACT and INTERACTIVE force the exact and the cheapest level; with ChooseByTime off
//      (distributed renders) an interactive frame draws the cheapest level, a still one exact;
//   e) one level is always level 0; a faster time replaces the estimate, a slower one moves it
//      half way; bad times are ignored, all forgotten on
//      ForgetTimes; the frame time of a window is 1 / DesiredUpdateRate;
//   f) the status line names the level and the reason.
#include "prTestUtilities.h"

#include "vtkNew.h"
#include "vtkParticleFrameBudget.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <string>

namespace
{
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  Failures += prTest::Check(condition, what) ? 0 : 1;
}
}

int TestParticleFrameBudget(int, char*[])
{
  vtkNew<vtkParticleFrameBudget> budget;
  // a) still frames
  Check(budget->ChooseLevel(1.0, 3) == 2, "a frame of StillFrameTime is still: exact");
  Check(budget->ChooseLevel(1.0e4, 3) == 2, "VTK's still rate (1e4 s): exact");
  Check(!budget->GetLastFrameInteractive(), "a still frame is not interactive");
  budget->ReportTime(2, 50.0); // exact costs far more than any frame
  Check(budget->ChooseLevel(500.0, 3) == 2, "ParaView's still render (500 s): exact at 50 s");

  // b) interactive frames
  vtkNew<vtkParticleFrameBudget> fresh;
  Check(fresh->ChooseLevel(0.2, 3) == 0, "nothing measured: the cheapest level");
  Check(fresh->GetLastFrameInteractive(), "0.2 s is an interactive frame");
  fresh->ReportTime(2, 0.05);
  Check(fresh->ChooseLevel(0.2, 3) == 2, "exact measured at 50 ms fits 200 ms");
  Check(fresh->ChooseLevel(0.04, 3) == 0, "exact does not fit 40 ms, level 1 unmeasured: 0");
  fresh->ReportTime(1, 0.03);
  Check(fresh->ChooseLevel(0.04, 3) == 1, "level 1 at 30 ms fits 40 ms");
  Check(fresh->ChooseLevel(0.01, 3) == 0, "nothing fits 10 ms: the cheapest");
  Check(fresh->GetLastLevel() == 0 && fresh->GetLastNumberOfLevels() == 3 &&
      fresh->GetLastFrameTime() == 0.01,
    "the last choice is remembered");

  vtkNew<vtkParticleFrameBudget> slowCheap;
  slowCheap->ReportTime(0, 0.2);
  slowCheap->ReportTime(1, 0.1);
  Check(slowCheap->ChooseLevel(0.01, 2) == 1, "nothing fits, the cheap level is slower: exact");
  slowCheap->ReportTime(0, 0.1);
  Check(slowCheap->ChooseLevel(0.01, 2) == 1, "equal times: the more accurate level");
  slowCheap->ReportTime(0, 0.05);
  Check(slowCheap->ChooseLevel(0.01, 2) == 0, "nothing fits, the cheap level is faster: cheap");

  vtkNew<vtkParticleFrameBudget> middle;
  middle->ReportTime(0, 0.01);
  middle->ReportTime(2, 1.0);
  Check(middle->ChooseLevel(0.1, 3) == 1, "the cheapest fits, the middle level unmeasured: tried");
  middle->ReportTime(1, 0.5);
  Check(middle->ChooseLevel(0.1, 3) == 0, "the middle level measured too slow: the cheapest");
  Check(middle->ChooseLevel(0.005, 3) == 0, "nothing fits: the fastest measured");

  // c) direction: over a sweep of frame times the level never falls as the time grows
  int previous = 0;
  bool monotone = true;
  for (double t = 1e-4; t < 2.0; t *= 1.3)
  {
    const int level = fresh->ChooseLevel(t, 3);
    monotone = monotone && level >= previous;
    previous = level;
  }
  Check(monotone, "a longer frame never draws a cheaper level");
  Check(previous == 2, "the sweep ends exact");

  // d) forced qualities
  fresh->SetQuality(vtkParticleFrameBudget::EXACT);
  Check(fresh->ChooseLevel(1e-6, 3) == 2, "EXACT: exact in a 1 us frame");
  fresh->SetQuality(vtkParticleFrameBudget::INTERACTIVE);
  Check(fresh->ChooseLevel(1e4, 3) == 0, "INTERACTIVE: the cheapest in a still frame");
  fresh->SetQuality(vtkParticleFrameBudget::ADAPTIVE);
  // ChooseByTime off (distributed renders): the cheapest while moving, whatever fits; exact still
  Check(fresh->ChooseLevel(0.5, 3) == 2, "by time: an interactive frame that fits is exact");
  fresh->ChooseByTimeOff();
  Check(fresh->ChooseLevel(0.9, 3) == 0 && fresh->ChooseLevel(0.5, 3) == 0,
    "ChooseByTime off: the cheapest in every interactive frame");
  Check(fresh->ChooseLevel(1e4, 3) == 2, "ChooseByTime off: a still frame is exact");
  Check(fresh->GetLastChoiceText("a|b|c").find("(still frame)") != std::string::npos,
    "ChooseByTime off: the still frame says so");
  fresh->ChooseLevel(0.5, 3);
  Check(fresh->GetLastChoiceText("a|b|c").find("the cheapest level on every process") !=
      std::string::npos,
    "ChooseByTime off: the interactive frame says why");
  fresh->ChooseByTimeOn();

  // e) one level, smoothing, bad times, forgetting
  Check(fresh->ChooseLevel(1e-6, 1) == 0 && fresh->ChooseLevel(1e4, 1) == 0, "one level: 0");
  vtkNew<vtkParticleFrameBudget> smooth;
  smooth->ReportTime(1, 0.1);
  smooth->ReportTime(1, 0.3);
  Check(std::abs(smooth->GetMeasuredTime(1) - 0.2) < 1e-12, "a slower time: half way");
  smooth->ReportTime(1, 0.15);
  smooth->ReportTime(1, 0.25);
  Check(std::abs(smooth->GetMeasuredTime(1) - 0.2) < 1e-12, "a faster time replaces the estimate");
  smooth->ReportTime(1, -1.0);
  smooth->ReportTime(1, std::numeric_limits<double>::quiet_NaN());
  smooth->ReportTime(1, std::numeric_limits<double>::infinity());
  smooth->ReportTime(-1, 0.5);
  Check(std::abs(smooth->GetMeasuredTime(1) - 0.2) < 1e-12, "negative, NaN, Inf times ignored");
  Check(
    smooth->GetMeasuredTime(0) < 0.0 && smooth->GetMeasuredTime(7) < 0.0, "unmeasured levels: -1");
  smooth->ForgetTimes();
  Check(smooth->GetMeasuredTime(1) < 0.0, "ForgetTimes forgets");
  Check(smooth->ChooseLevel(std::numeric_limits<double>::quiet_NaN(), 2) == 0,
    "a NaN frame time is not a still frame");

  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  window->SetDesiredUpdateRate(15.0);
  Check(std::abs(vtkParticleFrameBudget::GetFrameTime(renderer) - 1.0 / 15.0) < 1e-12,
    "frame time 1 / DesiredUpdateRate");
  window->SetDesiredUpdateRate(0.0);
  Check(std::isinf(vtkParticleFrameBudget::GetFrameTime(renderer)), "rate 0: unlimited");
  vtkNew<vtkRenderer> alone;
  Check(std::isinf(vtkParticleFrameBudget::GetFrameTime(alone)), "no window: unlimited");

  // f) the status line
  vtkNew<vtkParticleFrameBudget> told;
  told->ReportTime(1, 0.25);
  told->ChooseLevel(1.0 / 15.0, 2);
  const std::string text = told->GetLastChoiceText("sorted spheres|exact overlap");
  std::cout << "status: " << text << "\n";
  Check(text.find("sorted spheres (interactive frame of 66.7 ms)") == 0, "names level, reason");
  Check(text.find("exact overlap 250 ms") != std::string::npos, "gives the measured time");
  Check(text.find("sorted spheres not yet") != std::string::npos, "says what is unmeasured");
  told->ChooseLevel(1e4, 2);
  Check(told->GetLastChoiceText("a|b").find("b (still frame)") == 0, "still frame said");
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
