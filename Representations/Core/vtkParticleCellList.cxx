#include "vtkParticleCellList.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

//------------------------------------------------------------------------------
void vtkParticleCellList::Build(const double* xyz, vtkIdType n, const float* r, double h)
{
  this->Points = xyz;
  double lo[3] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
    std::numeric_limits<double>::max() };
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (r[i] > 0.0f)
    {
      for (int c = 0; c < 3; ++c)
      {
        lo[c] = std::min(lo[c], xyz[3 * i + c]);
      }
    }
  }
  // cell coordinates relative to the lowest corner; only an absurd extent over h reaches the
  // int64 limit, where cells merge (still correct, only slower)
  const double limit = 4.0e18;
  auto cell = [&](double x, double origin)
  { return static_cast<std::int64_t>(std::floor(std::min((x - origin) / h, limit))); };
  std::vector<std::pair<Key, vtkIdType>> keyed;
  keyed.reserve(static_cast<size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (r[i] > 0.0f)
    {
      const double* p = xyz + 3 * i;
      keyed.push_back({ { cell(p[0], lo[0]), cell(p[1], lo[1]), cell(p[2], lo[2]) }, i });
    }
  }
  vtkSMPTools::Sort(keyed.begin(), keyed.end());

  this->Cells.clear();
  this->Starts.clear();
  this->Order.resize(keyed.size());
  this->CellOf.assign(static_cast<size_t>(n), -1);
  for (size_t e = 0; e < keyed.size(); ++e)
  {
    if (e == 0 || !(keyed[e].first == keyed[e - 1].first))
    {
      this->Cells.push_back(keyed[e].first);
      this->Starts.push_back(static_cast<vtkIdType>(e));
    }
    this->Order[e] = keyed[e].second;
    this->CellOf[static_cast<size_t>(keyed[e].second)] =
      static_cast<std::int32_t>(this->Cells.size() - 1);
  }
  this->Starts.push_back(static_cast<vtkIdType>(keyed.size()));

  // the occupied cells among the 27 around each cell (binary searches, once per cell)
  const vtkIdType cells = static_cast<vtkIdType>(this->Cells.size());
  std::vector<std::array<std::int32_t, 27>> around(static_cast<size_t>(cells));
  vtkSMPTools::For(0, cells,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType c = begin; c < end; ++c)
      {
        const Key& key = this->Cells[c];
        int m = 0;
        for (int dx = -1; dx <= 1; ++dx)
        {
          for (int dy = -1; dy <= 1; ++dy)
          {
            for (int dz = -1; dz <= 1; ++dz)
            {
              const Key probe{ key.X + dx, key.Y + dy, key.Z + dz };
              auto it = std::lower_bound(this->Cells.begin(), this->Cells.end(), probe);
              around[c][m++] = (it != this->Cells.end() && *it == probe)
                ? static_cast<std::int32_t>(it - this->Cells.begin())
                : -1;
            }
          }
        }
      }
    });
  this->NeighborStarts.assign(static_cast<size_t>(cells) + 1, 0);
  this->NeighborCells.clear();
  for (vtkIdType c = 0; c < cells; ++c)
  {
    for (std::int32_t a : around[c])
    {
      if (a >= 0)
      {
        this->NeighborCells.push_back(a);
      }
    }
    this->NeighborStarts[c + 1] = static_cast<vtkIdType>(this->NeighborCells.size());
  }
}
