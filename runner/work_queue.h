// Tasks run by a fixed number of workers, the task with the smallest key first. A task may
// add more tasks while it runs (a lab's build adds its steps); run() returns when none is
// left and none is running.
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <queue>
#include <thread>
#include <tuple>
#include <vector>

namespace runner {

class WorkQueue {
 public:
  // (submission, lab, step): the earliest submission's work goes first, so that
  // submissions finish in order while the next one's labs fill any idle worker.
  using Key = std::tuple<std::size_t, std::size_t, std::size_t>;

  void add(Key key, std::function<void()> task) {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push({key, order_++, std::move(task)});
    ready_.notify_one();
  }

  void run(int workers) {
    const auto work = [this] {
      std::unique_lock<std::mutex> lock(mutex_);
      for (;;) {
        ready_.wait(lock, [this] { return !queue_.empty() || running_ == 0; });
        if (queue_.empty()) {  // nothing queued and nothing running that could add more
          ready_.notify_all();
          return;
        }
        std::function<void()> task = std::move(const_cast<Entry&>(queue_.top()).task);
        queue_.pop();
        ++running_;
        lock.unlock();
        task();  // its exceptions are its own: tasks catch what they throw
        lock.lock();
        --running_;
        ready_.notify_all();
      }
    };
    std::vector<std::thread> pool;
    for (int k = 0; k < std::max(1, workers); ++k) pool.emplace_back(work);
    for (std::thread& t : pool) t.join();
  }

 private:
  struct Entry {
    Key key;
    std::size_t order;  // among equal keys, first added first
    std::function<void()> task;
    bool operator<(const Entry& other) const {  // std::priority_queue takes the largest
      return std::tie(key, order) > std::tie(other.key, other.order);
    }
  };
  std::mutex mutex_;
  std::condition_variable ready_;
  std::priority_queue<Entry> queue_;
  std::size_t order_ = 0;
  int running_ = 0;
};

}  // namespace runner
