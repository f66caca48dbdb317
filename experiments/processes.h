// The processes of one multicpg job: one, or every rank of an MPI job when launched by mpirun
//. Every process runs the same command on the same arguments; the experiment runner
// (run_tasks) shares the runs among them, and only the primary process (rank 0) writes files and
// prints results. A command that runs under mpirun therefore calls run_tasks in every process,
// the same number of times in the same order (never from two threads at once), writes or prints
// only where is_primary_process(), and is listed in kSharedCommands (apps/main.cpp); the CLI
// refuses every other command under mpirun with -np > 1.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

namespace multicpg::experiments {

// The rank of the primary process in an MPI job.
constexpr int kPrimaryRank = 0;

// True in the process that owns the output and standard output: rank 0, or the only process.
bool is_primary_process();

// Processes in the job (1 unless launched by mpirun with -np > 1) and this one's index.
int process_count();
int process_rank();

// How a process ended: its exit code (0, 1 or 2) and, unless 0, the error line to print.
struct Ending {
  int code = 0;
  std::string line;
};

// Thrown by run_tasks in every process when another process of the job failed before it reached
// run_tasks; that process reports the error.
class FailedElsewhere : public std::runtime_error {
 public:
  explicit FailedElsewhere(int code)
      : std::runtime_error("another process of the job failed"), code_(code) {}
  int code() const { return code_; }

 private:
  int code_;
};

// Joins the MPI job when launched by mpirun (its environment names the job), so a plain run
// never loads or waits on MPI. Leaves it on destruction. One per program, in main.
class ProcessGroup {
 public:
  ProcessGroup(int& argc, char**& argv);
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;
  ~ProcessGroup();

  // Ends the job's work in this process, which ended as `ending` (main's result, or a
  // FailedElsewhere's code with no line): every process agrees on one exit code and exactly one
  // prints its error line, so a failing job ends with one line (under `mpirun -q`) and no process
  // is left waiting. Returns the exit code.
  int finish(const Ending& ending);
};

// Called by run_tasks in every process before it shares runs: throws FailedElsewhere when some
// process has already failed (it is in ProcessGroup::finish).
void agree_to_start();

#ifdef MULTICPG_MPI
// Messages between the processes (process_count() > 1). None busy-waits: a waiting process
// sleeps between looks, leaving the cores to the ones that compute (OpenMPI's blocking calls
// spin).
struct Message {
  int from = 0;  // rank of the sender
  int tag = 0;
  std::string text;
};
void send_message(int to, int tag, const std::string& text);
// The next message from `from` (nullopt: from any process) if one has arrived.
std::optional<Message> take_message(std::optional<int> from);
Message wait_for_message(std::optional<int> from);
// Sleeps between two looks at something pending.
void pause_between_polls();
// The primary's `text`, in every process (what the others pass is ignored).
std::string broadcast_from_primary(std::string text);
#endif

}  // namespace multicpg::experiments
