// Stepper: the fixed-step loop both simulators run (the networked robots of seed 000, sim/netsim,
// and the swarm exploration of seed 004, exploration/explorer), so that they step robots, sensors
// and the clock the same way (docs/design.md, "One stepping loop").
//  - the clock: t_k = k * dt, computed from the step index, never accumulated;
//  - the number of steps: the fewest that cover the time limit, ceil(time_limit / dt), where a
//    ratio within 1e-12 (relative) of an integer counts as that integer (0.3 / 0.1 is 3 steps);
//    more than 1e9 steps is refused with an error naming the option;
//  - periodic tasks (sensing, recording) at periods given in seconds, rounded to the nearest
//    whole number of steps, at least one: every(period) = max(1, round(period / dt));
//  - the order of the phases within step k, which runs from t_k to t_{k+1}:
//      sense(t_k)  on every sense_every-th step (k % sense_every == 0)
//      decide(t_k)
//      move(t_k -> t_{k+1})
//      record(t_{k+1})  when k + 1 is a multiple of record_every, and after the last step
//    then the stop condition done() is checked; the run ends at the time limit or when done();
//  - finish(t_end): once, after the last step (the networked robots handle the messages sent in
//    the last step there, as a robot process does; the explorer needs nothing).
#pragma once

#include <functional>
#include <string>

namespace voronav {

class Stepper {
 public:
  /// One step: index k, its start t = k * dt and its end t_end = (k + 1) * dt [s].
  struct Step {
    long k = 0;
    double t = 0.0;
    double t_end = 0.0;
  };
  /// The phases of a step, in the order they run. Empty functions are skipped.
  struct Phases {
    std::function<void(const Step&)> sense;
    std::function<void(const Step&)> decide;
    std::function<void(const Step&)> move;
    std::function<void(const Step&)> record;
    std::function<bool()> done;                ///< checked after every step's record
    std::function<void(double t_end)> finish;  ///< once, after the last step
    long sense_every = 1;                      ///< steps; see every()
    long record_every = 1;                     ///< steps; see every()
  };
  /// How a run ended.
  struct Outcome {
    long steps = 0;        ///< steps done
    double t_end = 0.0;    ///< steps * dt [s]
    bool stopped = false;  ///< done() ended it (else the time limit)
  };

  /// `dt_option` and `time_option` name the two values in error messages (e.g. "netsim.dt_s",
  /// "netsim.time_limit_s"). Throws voronav::Error for a dt or time limit that is not a positive
  /// finite number, or for more than 1e9 steps.
  Stepper(double dt_s, double time_limit_s, const std::string& dt_option,
          const std::string& time_option);

  [[nodiscard]] double dt() const { return dt_; }
  /// Number of steps of a full run.
  [[nodiscard]] long steps() const { return steps_; }
  /// t_k = k * dt [s].
  [[nodiscard]] double time(long k) const { return static_cast<double>(k) * dt_; }
  /// Steps per period: max(1, round(period_s / dt)). Throws voronav::Error naming `option` for a
  /// period that is not a positive finite number or longer than 1e9 steps.
  [[nodiscard]] long every(double period_s, const std::string& option) const;

  /// Runs the steps 0, 1, ... (phases above) until the time limit or done(); then finish().
  /// Throws voronav::Error when sense_every or record_every is < 1.
  Outcome run(const Phases& phases) const;

 private:
  double dt_ = 0.0;
  long steps_ = 0;
};

/// The number of steps a Stepper with these arguments runs (same checks, same errors).
[[nodiscard]] long step_count(double dt_s, double time_limit_s, const std::string& dt_option,
                              const std::string& time_option);

}  // namespace voronav
