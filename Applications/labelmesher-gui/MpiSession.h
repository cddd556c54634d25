// SPDX-License-Identifier: GPL-2.0-or-later
#ifndef labelmesher_gui_MpiSession_h
#define labelmesher_gui_MpiSession_h

/**
 * @file MpiSession.h
 * MPI for a program that meshes in a worker thread. The octree (p4est) calls
 * MPI; left to itself the core would start MPI on the first worker thread and
 * finalize it on the main thread at exit, which MPI forbids. This starts it on
 * the main thread with MPI_THREAD_SERIALIZED (one run at a time, from any
 * thread) and finalizes it there; under mpirun an MPI already up is left alone.
 */

namespace labelmesher
{
namespace gui
{

class MpiSession
{
public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

private:
  bool Started = false;
};

} // namespace gui
} // namespace labelmesher

#endif
