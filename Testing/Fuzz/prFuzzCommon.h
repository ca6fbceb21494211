// Shared by the reader fuzzers: read every time step of a reader, counting messages.
#ifndef prFuzzCommon_h
#define prFuzzCommon_h

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkDataSet.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <vector>

namespace prFuzz
{
// Counts the errors and warnings of the objects it observes.
class Counter : public vtkCommand
{
public:
  static Counter* New() { return new Counter; }
  void Execute(vtkObject*, unsigned long, void*) override { ++this->Count; }
  long long Count = 0;
};

// Update the reader's information, then every time step it offers. Returns the number of steps
// (-1 when the information pass gave none) and adds the points read to points.
inline int ReadAllSteps(vtkAlgorithm* reader, long long& points)
{
  reader->UpdateInformation();
  vtkInformation* info = reader->GetOutputInformation(0);
  if (!info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    return -1;
  }
  const int n = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const double* times = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  const std::vector<double> copy(times, times + n);
  for (double t : copy)
  {
    reader->UpdateTimeStep(t);
    points += vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0))->GetNumberOfPoints();
  }
  return n;
}
}

#endif
