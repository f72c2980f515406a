// The header lines of the benchmark's CSV tables (docs/bench/*.csv): each
// column names its unit as the run's tables do ("t [s]", "x [m]"), a count,
// a name or a yes/no (0/1) none. CPU time is in s; "s/s" is CPU seconds per
// simulated second.
#pragma once

namespace jl::bench {

// Speed against error, one table per study (pendulum, chainN, ladder, scaling,
// long_ladder, models). `parameter` is the step of a fixed-step method (s) or
// the tolerance of an adaptive one (a pure number); the error's unit is the
// study's.
inline constexpr const char* kWorkPrecisionPendulumColumns =
    "study,method,blocks,parameter [s or 1],cost [s/s],error [rad],finished,note";
inline constexpr const char* kWorkPrecisionColumns =
    "study,method,blocks,parameter [s or 1],cost [s/s],error [m],finished,note";
// Scaling: the "error" column holds the CPU time per block and step.
inline constexpr const char* kScalingColumns =
    "study,method,blocks,parameter [s or 1],cost [s/s],cost_per_block_step [ns],finished,note";

inline constexpr const char* kEventCostColumns =
    "blocks,window_from [s],window_to [s],steps,mean_step [s],events,instants,kinds,window_cpu [s],repetitions,"
    "repeatable,plain_step [s],plain_steps,plain_repetitions,plain_events,plain_step_cpu [s],event_cpu [s],"
    "cpu_per_event [s],cpu_per_instant [s],event_share,plain_steps_per_event,turning_steps,turning_events,"
    "turning_step_cpu [s],cpu_per_event_turning_baseline [s],eventful_steps,eventful_steps_cpu [s],"
    "cpu_per_event_in_eventful_steps [s],failure";

inline constexpr const char* kExamplesColumns =
    "scene,blocks,asked [s],simulated [s],cpu [s],cpu_per_simulated [s/s],faster_than_real_time,steps,integrator,"
    "adaptive,tolerance,automatic_step,smallest_step [s],largest_step [s],step_halvings,hinge_events,failure";

inline constexpr const char* kStabilityColumns =
    "blocks,omega_max_engine [rad/s],omega_max_reference [rad/s],omega_hand_upper [rad/s],omega_hand_airy [rad/s],"
    "lanczos_steps,ritz_residual [1/s^2],rk4_dt_limit_predicted [s],symplectic_euler_dt_limit_predicted [s],"
    "dormand_prince45_dt_limit_predicted [s],horizon [s],rk4_seeded_stays [s],rk4_seeded_grows [s],"
    "rk4_hanging_runs [s],rk4_hanging_fails [s],rk4_turned_runs [s],rk4_turned_fails [s],hanging_cost [s/s],"
    "turned_cost [s/s],hand_tension_factor,peak_tension_factor,peak_tension_time [s],rk4_dt_limit_at_peak [s],"
    "dopri_steps,dopri_rejected,dopri_mean_step [s],dopri_cost [s/s]";

inline constexpr const char* kBroadPhaseColumns =
    "blocks,still_from,pairs,calls,cpu_per_block_call [s],kept_cpu_per_block_call [s],build_cpu [s],failure";
inline constexpr const char* kContactExamplesColumns =
    "scene,asked [s],cpu_off [s],cpu_on [s],on_off_ratio,turns,"
    "steps_off,steps_on,events_off,events_on,strikes,same_sequence,"
    "largest_shift [s],part_at [s],largest_balance_on [J],failure_off,failure_on";

// The folding chain (bench/folding_study.cpp): every run of every engine,
// its errors against this engine's reference at 0.25, 0.5 and 1 s (centre:
// the largest block-centre distance; dissipated: |dissipated - reference|;
// closing: the largest first-closing difference; missing and extra: hinges
// the reference closes by 1 s and the run never does, and the reverse).
inline constexpr const char* kFoldingColumns =
    "blocks,engine,method,setting,stop_model,cpu [s],finished,centre_at_250ms [m],centre_at_500ms [m],"
    "centre_at_1s [m],dissipated_at_250ms [J],dissipated_at_500ms [J],dissipated_at_1s [J],closing_at_250ms [s],"
    "closing_at_500ms [s],closing_at_1s [s],missing,extra,failure";

}  // namespace jl::bench
