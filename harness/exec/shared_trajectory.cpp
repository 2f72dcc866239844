#include "harness/exec/shared_trajectory.hpp"

#include <future>
#include <map>
#include <mutex>

namespace rotbench {

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
            // A failure is not kept: the key is forgotten so that a later run tries again, and
            // the runs waiting now get the exception (each is then recorded as failed).
            {
                std::lock_guard lock(mutex);
                trajectories.erase(key);
            }
            promise.set_exception(std::current_exception());
        }
    }
    return shared.get();
}

}  // namespace rotbench
