// FFTW plans measured once per machine and shared through the wisdom file, under a file
// lock, so every process uses the same plan for a transform and gets the same bits.
#pragma once
#include <functional>
#include <mutex>

struct fftwf_plan_s;
struct fftw_plan_s;

namespace ob::ocean {

/// The FFTW planner (and plan destruction, wisdom I/O) is not thread-safe; fftwf_execute is.
/// Hold this while planning or destroying a plan.
std::mutex& fftwPlannerMutex();

/// A plan from the shared wisdom file ($XDG_CACHE_HOME/oceanbox/fftw_wisdom_f, else
/// ~/.cache/oceanbox/fftw_wisdom_f). `make(flags)` creates the plan with the FFTW planner
/// flags given (FFTW_MEASURE | FFTW_WISDOM_ONLY, FFTW_MEASURE or FFTW_ESTIMATE); it may
/// overwrite its arrays. The first process that needs a transform measures it and writes it
/// to the file under the lock; without a writable cache the plan is FFTW_ESTIMATE's (the same
/// every run, slower) and a warning says so once. Takes fftwPlannerMutex() itself.
fftwf_plan_s* planWithWisdom(const std::function<fftwf_plan_s*(unsigned flags)>& make);
/// The same for double-precision FFTW plans, through the wisdom file fftw_wisdom_d beside it.
fftw_plan_s* planWithWisdomDouble(const std::function<fftw_plan_s*(unsigned flags)>& make);

} // namespace ob::ocean
