// Shared FFTW wisdom: one measured plan per transform and machine, read and written under
// an inter-process file lock.
#include "core/fftw_wisdom.h"

#include "core/cache_file.h"
#include "core/log.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <fftw3.h>
#include <unistd.h>

namespace ob::ocean {

namespace {

// The wisdom file's inter-process lock (FileLock), held while a process reads the wisdom,
// plans and writes it back: processes planning at once then agree on one measured plan per
// transform instead of each measuring its own (different plans round differently).

// Called with both locks held. Writes a temporary file and renames it, so a reader never
// sees half a file. Returns false when the cache cannot be written.
template <class Export>
bool exportWisdom(const std::string& path, Export exportTo) {
    std::error_code ec;
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    if (exportTo(tmp.c_str())) {
        std::filesystem::rename(tmp, path, ec);
        if (!ec) return true;
    }
    std::filesystem::remove(tmp, ec);
    return false;
}

// FFTW_MEASURE picks a plan by timing, so two processes that each measure may get different
// bits: the plan comes from the wisdom file whenever it has one; the first process that needs
// it measures it and writes it there, under the file lock.
template <class Plan, class Make, class Import, class Export, class Destroy>
Plan planShared(const char* suffix, const Make& make, Import importFrom, Export exportTo, Destroy destroy) {
    std::lock_guard<std::mutex> lock(fftwPlannerMutex());
    const std::string path = cachePath(std::string("fftw_wisdom_") + suffix);  // suffix "f" single, "d" double
    FileLock fileLock(path);
    if (fileLock.held()) {
        importFrom(path.c_str());  // a missing or stale file: measure below
        Plan p = make(FFTW_MEASURE | FFTW_WISDOM_ONLY);
        if (p) return p;
        p = make(FFTW_MEASURE);
        if (!p || exportWisdom(path, exportTo)) return p;
        destroy(p);
    }
    static bool warned = false;
    if (!warned) {
        warned = true;
        logWarn("the FFTW wisdom cache %s cannot be written: using estimated FFT plans (the same in every run, but "
                "slower); set XDG_CACHE_HOME to a writable folder for measured ones",
                path.empty() ? "(no HOME or XDG_CACHE_HOME)" : path.c_str());
    }
    return make(FFTW_ESTIMATE);
}

} // namespace

std::mutex& fftwPlannerMutex() {
    static std::mutex mutex;
    return mutex;
}

fftwf_plan_s* planWithWisdom(const std::function<fftwf_plan_s*(unsigned flags)>& make) {
    return planShared<fftwf_plan>("f", make, fftwf_import_wisdom_from_filename, fftwf_export_wisdom_to_filename,
                                  fftwf_destroy_plan);
}

fftw_plan_s* planWithWisdomDouble(const std::function<fftw_plan_s*(unsigned flags)>& make) {
    return planShared<fftw_plan>("d", make, fftw_import_wisdom_from_filename, fftw_export_wisdom_to_filename,
                                 fftw_destroy_plan);
}

} // namespace ob::ocean
