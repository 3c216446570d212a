"""Which tests check each acceptance item of the seed inventory (its section 1, "best
acceptance tests, ranked by centrality": 39 rows, from RT-01 to MB-21).

``COVERAGE`` maps every row id to the pytest node ids of the tests that check the
row's own quantity -- the printed equation, pole, frequency, invariant, figure -- and a
one-line note of what they check; a test that merely runs a similar model is not listed.
A row that no test checks carries ``reason`` instead (or as well, for the part left out).

Checked here, without running the listed tests: every row id is in the table, and every
node id names an existing test function (found in the file's syntax tree, so the check
takes well under a second).  Parametrized tests are named by their function.
"""
import ast
from functools import lru_cache
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

# the row ids of INVENTORY section 1, in its rank order
SECTION_1 = [
    "RT-01", "MB-07", "MB-01/MB-02", "MB-03", "NM-02/NM-03", "EM-02", "EM-01",
    "NM-05/NM-06", "NM-24", "HY-11", "HY-02", "HY-19", "RT-04", "RT-08", "RT-07", "FR-03",
    "NM-26a", "NM-26b", "TF-09", "NM-17", "NM-19", "NM-29", "HY-20", "HY-08/09/10",
    "FR-05/FR-07", "CB-04", "RT-10", "RT-03", "MB-09", "MB-10", "MB-11/MB-12", "MB-14",
    "NM-21", "PE-01", "TF-04", "TF-08", "MB-16", "MB-17", "MB-21",
]

_EM = "tests/library/test_electromechanical.py::"
_LIN = "tests/analysis/test_linearize.py::"
_MB = "tests/library/test_multibody.py::"
_MB3 = "tests/library/test_multibody3d.py::"
_IR = "tests/models/test_index_reduction.py::"
_HY = "tests/library/test_hydraulics.py::"
_HL = "tests/library/test_hydraulic_lines.py::"
_FR = "tests/library/test_friction.py::"
_GAS = "tests/library/test_gas.py::"
_ACC = "tests/solvers/test_accuracy.py::"
_B = "tests/books/"

COVERAGE = {
    "RT-01": dict(tests=[
        _EM + "test_motor_gear_load_reduced_equation_3_12_and_lossless_gear",
        _IR + "test_two_inertias_through_ideal_gear_reflected_inertia",
        "tests/compiler/test_pantelides.py::test_gear_constraint_differentiated_twice",
        "tests/trust/test_geared_spring_drive.py::"
        "test_geared_spring_drive_from_rest_matches_the_reduced_ode",
    ], checks="(J_m + n^2 J_L) w_m' = T - n T_e (3.12) on the simulated motor-gear-load, "
              "power in = power out of the ideal gear, the reflected inertia, and the "
              "position constraint differentiated twice by Pantelides"),
    "MB-07": dict(tests=[
        _MB + "test_cart_pendulum_report_pulley_constraint_differentiated_twice",
        _MB + "test_cart_pendulum_effective_mass_7_161",
        _MB + "test_cart_pendulum_against_book_equations_7_161",
        _MB + "test_cart_pendulum_energy_balance_7_156",
    ], checks="m = m_v + J_m/r^2 of (7.161), the trajectory against the book's combined "
              "equations (7.161)-(7.162), V' = F x' (7.156), and the pulley constraint "
              "differentiated twice in the index report"),
    "MB-01/MB-02": dict(tests=[
        _IR + "test_pendulum_report_index_3_constraint_differentiated_twice",
        _IR + "test_pendulum_constraint_energy_and_angle_against_ode",
        _IR + "test_pendulum_full_rotations_switch_states",
        _IR + "test_double_pendulum_against_angle_ode",
        _MB + "test_double_pendulum_report_two_bars_differentiated_twice",
        _MB + "test_double_pendulum_constraints_and_vertical_crossings",
        _MB + "test_double_pendulum_from_joints_against_cartesian_model",
        "tests/solvers/test_pendulum_steps.py::"
        "test_states_switch_while_the_dropped_pivot_is_still_good",
        _B + "test_mb01_pendulum_printed_start.py::test_printed_start_is_made_consistent",
        _B + "test_mb01_pendulum_printed_start.py::"
        "test_passes_the_vertical_keeping_length_and_energy",
        _B + "test_mb01_pendulum_printed_start.py::test_angle_matches_the_angle_ode",
    ], checks="Cartesian (double) pendulum: length constraints (3.2.4) differentiated twice "
              "(index 3), |r| = l kept to 1e-8 through full turns and through x1 = 0, "
              "x2 = x1 (where the hand-reduced form is singular) by dynamic state "
              "selection, energy, and the angles against the angle ODE; from the printed "
              "start (0.34, 0.94, 0.94, -0.34) made consistent, ten passes of x = 0",
         reason="the fixed steps h = 1e-3 ... 1e-5 belong to the notes' own trapezoidal "
                "scheme, not to the model"),
    "MB-03": dict(tests=[
        _MB + "test_point_mass_chain_report_one_constraint_per_rod_differentiated_twice",
        _MB + "test_point_mass_chain_falls_like_the_joint_chain",
        "tests/compiler/test_pantelides.py::"
        "test_long_chain_differentiates_every_link_like_the_pendulum",
    ], checks="one index-3 constraint per added rod, each differentiated twice, in the "
              "index report; the chain's motion against the joint-coordinate chain"),
    "NM-02/NM-03": dict(tests=[
        _B + "test_nm02_nm03_index_examples.py::test_example_1_1_report_is_structural_index_1",
        _B + "test_nm02_nm03_index_examples.py::test_example_1_1_branch_y2_0",
        _B + "test_nm02_nm03_index_examples.py::"
        "test_example_1_1_branch_y2_1_is_flagged_at_the_initial_point",
        _B + "test_nm02_nm03_index_examples.py::test_example_1_1_branch_y2_1_run",
        _B + "test_nm02_nm03_index_examples.py::test_example_1_2_report_is_index_2",
        _B + "test_nm02_nm03_index_examples.py::test_example_1_2_solution",
    ], checks="Ex 1.1: structural index 1, branch y2 = 0 gives y3 = t, branch y2 = 1 "
              "(index 2) is flagged or gives y1 = t, y3 = 1; Ex 1.2: index 2 in the "
              "report and the solution against solve_ivp"),
    "EM-02": dict(tests=[
        _EM + "test_dc_motor_without_inductance_is_first_order_2_39",
        _EM + "test_dc_motor_with_zero_inductance_parameter",
        _EM + "test_dc_motor_step_matches_transfer_function_2_31",
        _LIN + "test_dc_motor_speed_poles_are_those_of_2_31",
    ], checks="L_a = 0 makes the armature equation algebraic and the motor first order, "
              "T_m w' = -w + u_a/K (2.39); with L_a > 0 the step response and poles are "
              "those of H(s) (2.31)"),
    "EM-01": dict(tests=[
        _EM + "test_dc_motor_composition_agrees_with_raw_equations_3_29",
        _EM + "test_dc_motor_energy_balance_3_33",
        _LIN + "test_dc_motor_angle_transfer_function_3_48",
        "tests/analysis/test_energy.py::test_dc_motor_energy_3_33_and_passivity",
        "tests/analysis/test_symbolic.py::test_dc_motor_matrices_in_the_parameters_3_41_3_43",
    ], checks="the composed motor equals (3.29)-(3.31), theta_m/u_a is (3.48) with "
              "T_a = L_a/R_a, T_m = J_m R_a/(K_E K_T), and V' = i_a u_a - w_m T_L - R_a "
              "i_a^2 (3.33) with the passivity report"),
    "NM-05/NM-06": dict(tests=[
        _ACC + "test_robertson_dae_matches_lsoda",
        _IR + "test_pendulum_constraint_energy_and_angle_against_ode",
    ], checks="the BDF corrector satisfies the algebraic rows at every output point: "
              "Robertson's conservation row to 1e-12, the pendulum's |r| = l to 1e-8; the "
              "DAE solution against LSODA at rtol 1e-12"),
    "NM-24": dict(tests=[
        _B + "test_nm24_bdf_coefficients.py::test_max_order_is_5",
        _B + "test_nm24_bdf_coefficients.py::test_constant_step_points_satisfy_the_book_formula",
        _B + "test_nm24_bdf_coefficients.py::test_bdf1_bdf2_damp_on_the_imaginary_axis",
        _B + "test_nm24_bdf_coefficients.py::test_bdf3_bdf4_grow_near_the_imaginary_axis",
        _B + "test_nm24_bdf_coefficients.py::test_stiff_limit_roots_go_to_zero",
        _B + "test_nm24_bdf_coefficients.py::test_stiff_mode_is_damped_out_in_one_step",
    ], checks="constant-step points satisfy the printed BDF formulas, BDF1/BDF2 damp on "
              "the imaginary axis, BDF3/4 do not, roots -> 0 as lambda h -> inf",
         reason="order 6 is not implemented (max order 5, as DASSL/IDA)"),
    "HY-11": dict(tests=[
        _LIN + "test_hydraulic_loop_gain_margin_is_6_dB_at_K_v_40",
        _LIN + "test_hydraulic_closed_loop_stable_exactly_below_2_zeta_w",
        _LIN + "test_valve_controlled_motor_from_the_library",
        _HY + "test_valve_motor_hydraulic_frequency_and_damping_4_101",
        _HY + "test_p_controlled_motor_poles_and_stability_limit_4_107_to_4_112",
    ], checks="w_h^2 = 4 beta D_m^2/(V_t J_t), zeta_h = (K_ce/D_m) sqrt(beta J_t/V_t), "
              "6 dB gain margin at K_v = 40 (|L(j w_h)| = 0.5), stable iff "
              "K_v < 2 zeta_h w_h"),
    "HY-02": dict(tests=[
        _HY + "test_regularized_orifice_is_ellman_piche_4_9_in_area_form_4_13",
        "tests/library/test_hydraulic_branches.py::"
        "test_variable_orifice_closes_through_zero_area_4_13",
    ], checks="the regularized orifice is (4.9)/(4.13): laminar below the transition, "
              "turbulent above, finite slope at dp = 0, closing through zero area"),
    "HY-19": dict(tests=[
        _HL + "test_lumped_line_closed_at_both_ends_examples_67_68",
        _HL + "test_lumped_line_closed_at_one_end_example_69",
        _HL + "test_lumped_line_frequencies_approach_the_exact_k_pi_c_over_L",
    ], checks="Ex 67/68: 2 sqrt(2) c/L (n = 2), 3 c/L and 3 sqrt(3) c/L (n = 3); Ex 69: "
              "1.5 c/L; the chain's frequencies converging as O(1/n^2) to k pi c/L"),
    "RT-04": dict(tests=[
        _EM + "test_resonance_of_elastic_transmission_3_87",
        _EM + "test_anti_resonance_of_elastic_transmission_3_88",
        _EM + "test_elastic_transmission_rigid_mode_3_76",
        _LIN + "test_elastic_load_undamped_zeros_and_poles",
        _LIN + "test_elastic_load_damped_zero_damping_ratio",
        _B + "test_rt04_elastic_transmission_frequency_response.py::"
        "test_printed_resonance_and_anti_resonance",
        _B + "test_rt04_elastic_transmission_frequency_response.py::"
        "test_frequency_response_is_3_85_and_3_86",
        _B + "test_rt04_elastic_transmission_frequency_response.py::"
        "test_motor_speed_response_is_positive_real_3_95_3_96",
        _B + "test_rt04_elastic_transmission_frequency_response.py::"
        "test_motor_angle_phase_3_97_and_load_angle_drop",
    ], checks="w_1 = sqrt(K/J_e), zeta_1 (3.87), w_a = sqrt(J_m/J) w_1, zeta_a (3.88) as "
              "poles and zeros (with Fig. 3.11's K = 0.5, J_m = J_L = 1, D = 0.01: 1 rad/s, "
              "0.01, 0.7071 rad/s), H(jw) = (3.85)/(3.86), Re H_wm >= 0 (3.95), "
              "|angle H_wm| <= 90 deg (3.96), -180 <= angle H_theta_m <= 0 (3.97)"),
    "RT-08": dict(tests=[
        "tests/library/test_backlash.py::test_free_flight_impact_and_contact_against_closed_form",
        "tests/library/test_backlash.py::"
        "test_impacts_conserve_angular_momentum_and_stop_the_relative_motion",
        "tests/library/test_backlash.py::test_square_wave_drive_example_stays_in_the_dead_zone",
        "tests/library/test_backlash.py::"
        "test_contact_follows_the_reduced_rigid_model_under_a_varying_torque",
    ], checks="the three models (3.122)-(3.124) switched by events at phi = +-delta: "
              "free flight and contact against closed forms, the impacts, and contact "
              "following the reduced rigid model (3.12)/(3.123)"),
    "RT-07": dict(tests=[
        "tests/library/test_rotational.py::test_elastic_gear_with_deadzone_3_119",
    ], checks="the piecewise torque (3.119) with zero crossings at |phi| = delta"),
    "FR-03": dict(tests=[
        _FR + "test_karnopp_stick_slip_times_and_exact_sticking",
        _FR + "test_rotational_karnopp_breaks_away_at_F_s",
        "tests/trust/test_geared_stick_slip.py::"
        "test_driven_load_sticks_while_the_applied_torque_is_below_F_s",
        "tests/trust/test_geared_stick_slip.py::test_driven_run_matches_the_mode_by_mode_reference",
    ], checks="F_f = sat(F_a, F_c) at v = 0 (5.22)/(5.23): v stays exactly 0 while the "
              "applied force is below the static level, stick/slip times against a "
              "mode-by-mode reference"),
    "NM-26a": dict(tests=[
        _B + "test_nm26_pneumatic_spring.py::test_minimum_energy_is_7000_J",
        _B + "test_nm26_pneumatic_spring.py::test_jacobian_is_14_103",
        _B + "test_nm26_pneumatic_spring.py::test_energy_is_kept_at_tight_tolerance",
        _B + "test_nm26_pneumatic_spring.py::test_implicit_euler_only_loses_energy",
        _GAS + "test_pneumatic_spring_frequency_is_14_104",
        _GAS + "test_pneumatic_spring_follows_14_100_and_keeps_its_energy",
    ], checks="w_0 = 3.7 rad/s at x* = 1 (14.104), E_min = 7000 J, the Jacobian (14.103), "
              "energy kept by BDF at tight tolerance and only lost by implicit Euler",
         reason="the Euler/RK4/Gauss/Radau/Lobatto comparisons are about methods acausal "
                "does not have"),
    "NM-26b": dict(tests=[
        _B + "test_nm26_pneumatic_spring.py::test_two_mass_eigenvalues",
        _B + "test_nm26_pneumatic_spring.py::test_two_mass_equilibrium_is_1_and_1_minus_m2_g_over_K",
        _B + "test_nm26_pneumatic_spring.py::test_two_mass_energy_and_trajectory",
        _GAS + "test_two_mass_pneumatic_spring_eigenvalues",
        _GAS + "test_two_mass_pneumatic_spring_follows_14_144",
    ], checks="eigenvalues +-j3.7 and +-j1000, the equilibrium, energy and trajectory "
              "of the two-mass spring (14.144)",
         reason="the Gauss aliasing and Lobatto IIIC one-step damping at h = 0.05 concern "
                "methods acausal does not have; BDF's damping of the fast mode and its "
                "step-size control on it are not tested"),
    "TF-09": dict(tests=[
        _B + "test_tf09_robertson.py::test_linear_invariant_is_kept",
        _B + "test_tf09_robertson.py::test_values_match_radau",
        _ACC + "test_robertson_dae_matches_lsoda",
        _ACC + "test_robertson_final_state_matches_ida",
    ], checks="(14.13) as three ODEs: y1 + y2 + y3 = 1 kept to 1e-10 by BDF without being "
              "an equation, values against Radau at rtol 1e-10; the DAE form against LSODA "
              "and IDA"),
    "NM-17": dict(tests=[
        _B + "test_nm17_step_size_control.py::test_step_scales_as_tolerance_to_one_over_p_plus_one",
        _B + "test_nm17_step_size_control.py::test_exponent_is_not_that_of_another_order",
        _ACC + "test_damped_oscillator_tolerance_proportionality",
    ], checks="the settled step scales as tol^(1/(p+1)) of (14.197) for p = 1, 2, 3, 5; the "
              "global error is proportional to the tolerance",
         reason="the PI rule (14.202)-(14.203) is not implemented (the IDA rule is)"),
    "NM-19": dict(tests=[
        _B + "test_nm19_event_location.py::test_roots_are_those_of_the_dense_output",
        _B + "test_nm19_event_location.py::test_located_times_converge_to_the_exact_crossings",
        "tests/solvers/test_events.py::test_bounce_times_match_closed_form",
        _ACC + "test_van_der_pol_stiff_matches_radau",
    ], checks="roots of g(y_n(alpha)) = 0 (14.221) on the dense output, against a run "
              "without events and the exact crossings; bounce times in closed form; Van "
              "der Pol crossings against brentq on a Radau solution"),
    "NM-29": dict(tests=[
        _B + "test_nm29_three_body.py::test_orbit_closes_after_one_period",
        _B + "test_nm29_three_body.py::test_closure_error_falls_with_the_tolerance",
        _B + "test_nm29_three_body.py::test_jacobi_integral_is_kept",
        _B + "test_nm29_three_body.py::test_trajectory_matches_an_independent_integrator",
    ], checks="return to the IC after the printed period T, Jacobi integral (4.2.3) "
              "constant, the trajectory against DOP853 at rtol 1e-12",
         reason="ode45's printed step counts are not compared (step counts are not asserted)"),
    "HY-20": dict(tests=[
        _HL + "test_water_hammer_joukowsky_pressure_rise_11_125",
    ], checks="p_2 = rho c v (11.125) as the plateau of a lumped line closed by a valve "
              "(oil, rho = 800, c = 1250, v = 2 m/s: 20 bar); the book's 75/50 bar at "
              "5 m/s are the same product"),
    "HY-08/09/10": dict(tests=[
        _HY + "test_volume_filled_through_an_orifice_4_64",
        _HY + "test_piston_volume_and_single_acting_cylinder_agree_4_64",
        _HY + "test_cylinder_with_mass_load_4_83_to_4_85",
        _HY + "test_hydrostatic_gear_4_122",
        "tests/analysis/test_energy.py::test_valve_controlled_motor_energy_audit_4_66",
    ], checks="(V/beta) p' + V' = q_in - q_out (4.64) with a moving boundary, "
              "F = A_1 p_1 - A_2 p_2 (4.83)-(4.85), T = D_m (p_1 - p_2) through the motor's "
              "w_h, zeta_h, and W_p = 1/2 (V/beta) p^2 (4.66) in the energy audit"),
    "FR-05/FR-07": dict(tests=[
        _FR + "test_dahl_forward_motion_5_38",
        _FR + "test_lugre_steady_state_is_the_stribeck_curve_5_48",
        _B + "test_fr07_lugre_passivity.py::test_creep_is_the_steady_state",
        _B + "test_fr07_lugre_passivity.py::test_dissipation_is_nonnegative_inside_the_bound",
        _B + "test_fr07_lugre_passivity.py::test_dissipation_turns_negative_outside_the_bound",
    ], checks="Dahl F = F_c (1 - exp(-sigma x/F_c)) (5.38) with F_c = 2, sigma = 0.5; LuGre "
              "steady state g(v) sgn(v) (5.48); passive iff sigma_1 <= sigma_2 F_c/(F_s - "
              "F_c) (5.54), on both sides of the bound"),
    "CB-04": dict(tests=[
        _B + "test_cb04_tanker_autopilot.py::test_book_poles_with_kp_14",
        _B + "test_cb04_tanker_autopilot.py::test_printed_matlab_command_with_kp_20",
        _B + "test_cb04_tanker_autopilot.py::test_step_response_is_the_closed_form",
        "tests/trust/test_autopilot_transfer_function.py::test_book_poles_of_the_lead_lag_autopilot",
    ], checks="closed-loop poles -0.5609, -0.0295 +- j0.0303 with K_p = 14 (the printed "
              "K_p = 20 gives others), step response in closed form"),
    "RT-10": dict(tests=[
        "tests/analysis/test_statespace.py::test_mass_spring_damper_poles_and_resonance_2_14_2_16",
        "tests/library/test_translational.py::test_mass_spring_damper_energy_balance_2_60",
        "tests/analysis/test_energy.py::test_mass_spring_damper_energy_decays_as_2_60",
    ], checks="poles from w_0 = sqrt(k/m), zeta = d/(2 sqrt(km)), H(j w_0) = -j/(2 zeta k) "
              "at -90 deg, and V' = -d x'^2 (2.60)"),
    "RT-03": dict(tests=[
        _B + "test_rt03_stribeck_stability.py::test_pole_is_the_closed_form",
        _B + "test_rt03_stribeck_stability.py::test_stability_follows_the_corrected_condition",
        _B + "test_rt03_stribeck_stability.py::test_printed_condition_is_wrong_where_they_differ",
        _B + "test_rt03_stribeck_stability.py::test_small_perturbation_grows_at_the_linear_rate",
    ], checks="the linearized pole at w_m and the stability condition (3.26) (corrected; "
              "where the printed one differs it is shown wrong), perturbation growth"),
    "MB-09": dict(tests=[
        _MB + "test_ball_and_beam_initial_acceleration_7_142",
        _MB + "test_ball_and_beam_against_book_equations_7_133",
        _MB + "test_ball_and_beam_energy_balance_7_136",
        _B + "test_mb09_ball_and_beam_linear.py::test_linearization_of_the_full_model",
        _B + "test_mb09_ball_and_beam_linear.py::test_small_ball_gives_the_corrected_7_143",
    ], checks="V' = theta' T (7.136), the trajectory against (7.133)-(7.134) with "
              "J_2 + mR^2 = 7/5 mR^2, x'' = 5/7 g theta and the (corrected) fourth-order "
              "linearization (7.143)"),
    "MB-10": dict(tests=[
        _MB3 + "test_furuta_against_lagrange_equations_8_45",
        _MB3 + "test_furuta_power_balance_7_196",
    ], checks="the component model against Lagrange's (8.45)-(8.46) and V' = theta_1' T "
              "(7.196)"),
    "MB-11/MB-12": dict(tests=[
        _B + "test_mb11_two_link_manipulator.py::test_trajectory_matches_the_book_equations",
        _B + "test_mb11_two_link_manipulator.py::test_mdot_minus_2c_is_skew_symmetric",
        _B + "test_mb11_two_link_manipulator.py::test_energy_rate_is_joint_power",
    ], checks="m_11, m_12, m_22 (8.77)-(8.79) through the trajectory, M' - 2C skew (8.70), "
              "E' = q'^T tau (8.73)"),
    "MB-14": dict(tests=[
        _B + "test_mb14_quaternion_normalization.py::"
        "test_norm_error_decays_with_time_constant_one_over_lambda",
        _MB3 + "test_racket_quaternion_norm_kept_over_100_s",
    ], checks="with (6.336), e = 1 - Q^T Q follows e' = -lam e (1 - e) (time constant "
              "1/lam, lam = 100 and 10) from Q^T Q = 1.02; |Q| kept over 100 s of tumbling",
         reason="the projection alternative (6.338) is not offered by the library"),
    "NM-21": dict(tests=[], reason="no invariant projection / post-stabilization option "
                  "exists: index reduction keeps the constraints as equations (so drift is "
                  "not an issue there), and an ODE's invariants are only monitored"),
    "PE-01": dict(tests=[
        "tests/analysis/test_estimate.py::test_tank_outlet_area_from_noisy_outflow",
        "tests/analysis/test_sensitivity.py::"
        "test_forward_and_finite_difference_estimates_agree_for_the_tank",
    ], checks="the outlet a = 1/sqrt(2g) ~ 0.226 recovered from noisy outflow (Table 7.3 "
              "noise) within 2 standard errors and 100 x closer than the notes' 0.2303",
         reason="the notes' iteration counts (40, 51, no convergence at 1e-6) belong to "
                "their own optimizer"),
    "TF-04": dict(tests=[
        _B + "test_tf04_water_turbine.py::test_zero_pole_and_gains_are_11_113",
        _B + "test_tf04_water_turbine.py::test_full_load_form_11_114",
        _B + "test_tf04_water_turbine.py::test_gate_step_against_the_hand_written_column",
        _B + "test_tf04_water_turbine.py::test_compressible_penstock_tends_to_11_119",
    ], checks="dT_t/dA = (r_t rho q_0^2/A_0^2)(1 - T_r s)/(1 + (T_r/2) s) (11.114) with "
              "its non-minimum-phase zero; the gate step against hand-written equations"),
    "TF-08": dict(tests=[
        _GAS + "test_rotating_stall_settles_at_the_closed_form_equilibrium",
        _GAS + "test_rotating_stall_transient_follows_dop853",
        _GAS + "test_design_point_is_unstable_the_way_b_says",
        _GAS + "test_surge_follows_dop853",
        _GAS + "test_surge_is_a_limit_cycle_without_stall",
    ], checks="with the printed constants and IC: B = 0.1 falls into rotating stall "
              "(closed-form equilibrium, J > 0), B = 1 into a surge limit cycle without "
              "stall, both against DOP853 at rtol 1e-10"),
    "MB-16": dict(tests=[
        "tests/library/test_wheelset.py::test_the_contact_dae_is_index_3_as_the_notes_state",
        "tests/library/test_wheelset.py::"
        "test_consistent_initialization_solves_the_contact_constraints",
        "tests/library/test_wheelset.py::test_stability_statements_of_section_5_9",
        "tests/library/test_wheelset.py::"
        "test_contact_dae_linearized_agrees_with_the_small_motion_model",
        "tests/library/test_wheelset.py::test_contact_dae_hunting_is_limited_by_the_flange",
        "tests/library/test_wheelset.py::test_klingel_wavelength_in_the_creep_free_limit",
    ], checks="the notes' contact DAE is index 3 (as stated); V = 100 m/s, k_s = 1.823 MN/m: "
              "delta = 0.05 stable, 0.08 unstable; V = 20 m/s unsuspended unstable and "
              "flange-limited; Klingel's wavelength in the creep-free limit",
         reason="the printed outcomes are qualitative (lost figures): verdicts, not "
                "trajectories, are checked"),
    "MB-17": dict(tests=[
        "tests/library/test_bicycle.py::test_matrices_of_appendix_a_reproduce_the_printed_ones",
        "tests/library/test_bicycle.py::test_eigenvalues_of_table_2",
        "tests/library/test_bicycle.py::test_weave_and_capsize_speeds_of_table_2",
        "tests/library/test_bicycle.py::test_bifurcation_speed_of_table_2",
    ], checks="the benchmark bicycle the notes follow (Meijaard et al. 2007): M, C1, K0, K2, "
              "the eigenvalues over speed, weave 4.29 and capsize 6.02 m/s",
         reason="the notes' own matrix entries (6.8.2)-(6.8.5) are garbled; the benchmark's "
                "published values are checked instead"),
    "MB-21": dict(tests=[], reason="not reproducible: the aerodynamic data of the re-entry "
                  "vehicle are not given in 000 §8 (INVENTORY says so), so neither the "
                  "consistent alpha_0, beta_0 nor Table 8.1 can be recomputed"),
}


@lru_cache(maxsize=None)
def _test_names(path: str) -> frozenset:
    """The test functions of a file, as 'name' and 'Class::name'."""
    tree = ast.parse((ROOT / path).read_text(encoding="utf-8"), filename=path)
    names = set()
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            names.add(node.name)
        elif isinstance(node, ast.ClassDef):
            names.update(f"{node.name}::{item.name}" for item in node.body
                         if isinstance(item, (ast.FunctionDef, ast.AsyncFunctionDef)))
    return frozenset(n for n in names if n.split("::")[-1].startswith("test"))


def test_every_section_1_row_is_in_the_table():
    assert len(SECTION_1) == len(set(SECTION_1)) == 39
    assert set(COVERAGE) == set(SECTION_1), (set(SECTION_1) ^ set(COVERAGE))


@pytest.mark.parametrize("row", SECTION_1)
def test_row_names_existing_tests_or_a_reason(row):
    entry = COVERAGE[row]
    assert entry["tests"] or entry.get("reason"), f"{row}: neither tests nor a reason"
    if entry["tests"]:
        assert entry.get("checks"), f"{row}: the tests are listed without what they check"
    for node in entry["tests"]:
        path, _, name = node.partition("::")
        assert path.startswith("tests/") and path.endswith(".py") and name, node
        assert (ROOT / path).is_file(), f"{row}: no file {path}"
        assert name in _test_names(path), f"{row}: no test {name} in {path}"
