#include "harness/exec/shared_trajectory.hpp"

#include "harness/exec/interrupt.hpp"

#include <exception>
#include <future>
#include <new>
#include <map>
#include <mutex>

namespace rotbench {
namespace {

bool out_of_memory(const std::exception_ptr& failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const std::bad_alloc&) {
        return true;
    } catch (...) {
        return false;
    }
}

}  // namespace

std::shared_ptr<const Trajectory> shared_trajectory(const std::string& key, const std::function<Trajectory()>& compute) {
    using Shared = std::shared_future<std::shared_ptr<const Trajectory>>;
    static std::mutex mutex;
    static std::map<std::string, Shared> trajectories;
    std::promise<std::shared_ptr<const Trajectory>> promise;
    Shared shared;
    bool ours = false;
    {
        std::lock_guard lock(mutex);
        auto [it, inserted] = trajectories.try_emplace(key);
        if (inserted) it->second = promise.get_future().share();
        shared = it->second;
        ours = inserted;
    }
    if (ours) {
        try {
            promise.set_value(std::make_shared<const Trajectory>(compute()));
        } catch (...) {
            // The runs waiting now get the exception (each is then recorded as failed). A
            // failure of the scene's own (a reference past its step budget) is kept, so that
            // the other schemes' runs fail at once instead of paying for it again; one of the
            // moment (an interrupt, memory running out) is forgotten, and a later run tries again.
            if (interrupt_signal() || out_of_memory(std::current_exception())) {
                std::lock_guard lock(mutex);
                trajectories.erase(key);
            }
            promise.set_exception(std::current_exception());
        }
    }
    return shared.get();
}

}  // namespace rotbench
