#include "vtkParticleStageTimer.h"

#include "vtkParticleCompat.h"

//------------------------------------------------------------------------------
vtkParticleStageTimer::vtkParticleStageTimer(int stages)
  : Queries(static_cast<std::size_t>(stages))
  , Times(static_cast<std::size_t>(stages), 0.0)
{
}

//------------------------------------------------------------------------------
void vtkParticleStageTimer::StartFrame(bool on)
{
  this->Read(); // (the last frame's results, or the queries of a frame nobody asked about)
  this->On = on;
  if (on)
  {
    this->Read_ = false;
    for (double& t : this->Times)
    {
      t = 0.0;
    }
  }
}

//------------------------------------------------------------------------------
void vtkParticleStageTimer::Begin(int stage)
{
  if (!this->On || this->Running || stage < 0 || stage >= static_cast<int>(this->Queries.size()))
  {
    return;
  }
  GLuint query = 0;
  glGenQueries(1, &query);
  glBeginQuery(GL_TIME_ELAPSED, query);
  this->Queries[static_cast<std::size_t>(stage)].push_back(query);
  this->Running = true;
}

//------------------------------------------------------------------------------
void vtkParticleStageTimer::End()
{
  if (this->Running)
  {
    glEndQuery(GL_TIME_ELAPSED);
    this->Running = false;
  }
}

//------------------------------------------------------------------------------
void vtkParticleStageTimer::Read()
{
  if (this->Read_)
  {
    return;
  }
  for (std::size_t stage = 0; stage < this->Queries.size(); ++stage)
  {
    std::vector<unsigned int>& queries = this->Queries[stage];
    GLuint64 total = 0;
    for (GLuint query : queries)
    {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(query, GL_QUERY_RESULT, &ns);
      total += ns;
    }
    if (!queries.empty())
    {
      glDeleteQueries(static_cast<GLsizei>(queries.size()), queries.data());
    }
    queries.clear();
    this->Times[stage] = 1e-9 * static_cast<double>(total);
  }
  this->Read_ = true;
}

//------------------------------------------------------------------------------
double vtkParticleStageTimer::Seconds(int stage)
{
  if (stage < 0 || stage >= static_cast<int>(this->Times.size()))
  {
    return 0.0;
  }
  this->Read();
  return this->Times[static_cast<std::size_t>(stage)];
}

//------------------------------------------------------------------------------
void vtkParticleStageTimer::Release(bool contextCurrent)
{
  for (std::vector<unsigned int>& queries : this->Queries)
  {
    if (contextCurrent && !queries.empty())
    {
      glDeleteQueries(static_cast<GLsizei>(queries.size()), queries.data());
    }
    queries.clear();
  }
  this->Running = false;
  this->Read_ = true;
}
