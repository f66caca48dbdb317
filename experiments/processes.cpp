#include "experiments/processes.h"

#include <cstdlib>
#include <iostream>

#ifdef MULTICPG_MPI
#include <mpi.h>

#include <chrono>
#include <thread>
#endif

namespace multicpg::experiments {
namespace {

#ifdef MULTICPG_MPI
// Between two looks at a pending message or collective. A run takes a second or more (a trial
// is 400+ simulated steps), so a millisecond of latency per message is nothing, and a waiting
// process wakes a thousand times a second instead of spinning on a core.
constexpr std::chrono::milliseconds kPollInterval{1};

// Environment variables that OpenMPI's launcher (mpirun, or a PMIx launcher such as srun) sets in
// every process it starts.
constexpr const char* kLaunchedByMpi[] = {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK"};

bool launched_by_mpi() {
  for (const char* name : kLaunchedByMpi) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

bool joined = false;  // MPI_Init_thread was called by ProcessGroup
// Set once this process has agreed with the others that the job failed (in agree_to_start):
// ProcessGroup::finish must not agree a second time.
bool agreed_failure = false;

// Completes `request`, sleeping between looks (OpenMPI's blocking calls spin on a core).
void wait_politely(MPI_Request& request) {
  for (;;) {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done != 0) return;
    pause_between_polls();
  }
}
#endif

int rank = 0;
int size = 1;

#ifdef MULTICPG_MPI
// Every process passes its exit code; returns the largest and the lowest rank that passed it.
struct Agreement {
  int code;
  int rank;
};
Agreement agree(int code) {
  // MPI_MINLOC on -code: the largest code, and of the processes with it the lowest rank.
  struct {
    int value;
    int rank;
  } mine{-code, rank}, all{};
  MPI_Request request;
  MPI_Iallreduce(&mine, &all, 1, MPI_2INT, MPI_MINLOC, MPI_COMM_WORLD, &request);
  wait_politely(request);
  return {-all.value, all.rank};
}
#endif

}  // namespace

bool is_primary_process() {
  return rank == kPrimaryRank;
}

int process_count() {
  return size;
}

int process_rank() {
  return rank;
}

ProcessGroup::ProcessGroup([[maybe_unused]] int& argc, [[maybe_unused]] char**& argv) {
#ifdef MULTICPG_MPI
  if (!launched_by_mpi()) return;
  // Only the thread that calls run_tasks talks to the other processes, never two at once.
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
  joined = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
#endif
}

ProcessGroup::~ProcessGroup() {
#ifdef MULTICPG_MPI
  if (joined) MPI_Finalize();
#endif
}

int ProcessGroup::finish(const Ending& ending) {
  Ending agreed = ending;
#ifdef MULTICPG_MPI
  if (agreed_failure) return ending.code;
  if (size > 1) {
    const Agreement a = agree(ending.code);
    agreed.code = a.code;
    if (a.rank != rank) agreed.line.clear();
  }
#endif
  if (agreed.code != 0 && !agreed.line.empty()) std::cerr << agreed.line << "\n";
  return agreed.code;
}

void agree_to_start() {
#ifdef MULTICPG_MPI
  if (size == 1) return;
  const Agreement a = agree(0);
  if (a.code != 0) {
    agreed_failure = true;
    throw FailedElsewhere(a.code);
  }
#endif
}

#ifdef MULTICPG_MPI
void send_message(int to, int tag, const std::string& text) {
  MPI_Request request;
  MPI_Isend(text.data(), static_cast<int>(text.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD,
            &request);
  wait_politely(request);
}

std::optional<Message> take_message(std::optional<int> from) {
  int arrived = 0;
  MPI_Message handle;
  MPI_Status status;
  MPI_Improbe(from.value_or(MPI_ANY_SOURCE), MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &handle,
              &status);
  if (arrived == 0) return std::nullopt;
  int length = 0;
  MPI_Get_count(&status, MPI_CHAR, &length);
  Message m{status.MPI_SOURCE, status.MPI_TAG, std::string(static_cast<std::size_t>(length), '\0')};
  MPI_Mrecv(m.text.data(), length, MPI_CHAR, &handle, MPI_STATUS_IGNORE);
  return m;
}

Message wait_for_message(std::optional<int> from) {
  for (;;) {
    if (std::optional<Message> m = take_message(from)) return std::move(*m);
    pause_between_polls();
  }
}

void pause_between_polls() {
  std::this_thread::sleep_for(kPollInterval);
}

std::string broadcast_from_primary(std::string text) {
  unsigned long long length = text.size();
  MPI_Request request;
  MPI_Ibcast(&length, 1, MPI_UNSIGNED_LONG_LONG, kPrimaryRank, MPI_COMM_WORLD, &request);
  wait_politely(request);
  text.resize(length);
  MPI_Ibcast(text.data(), static_cast<int>(length), MPI_CHAR, kPrimaryRank, MPI_COMM_WORLD,
             &request);
  wait_politely(request);
  return text;
}
#endif

}  // namespace multicpg::experiments
