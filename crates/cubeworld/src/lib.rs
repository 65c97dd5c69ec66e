//! The execution check: a cube world in which a plan is carried out by grippers and
//! checked against the paper's own grounding.
//!
//! A [`World`] holds a table, 5 cm cubes and one or two grippers, laid out from a
//! problem's initial state (cubes in rows on the table, towers where `ontop` says so,
//! hands at rest beside the table, open). [`execute`] takes each step of a plan, reads
//! its type from the action's name (`put2` is a put), and turns it into motion
//! primitives of that type (reach, grasp, lift, carry, place, slide, release, creep,
//! stop, rise, retreat): candidates are tried on a copy of the world and the one whose
//! frames, grounded with the Table 2 grounding ([`grounding::Grounder`], default
//! thresholds), give the step's add effects and none of its delete effects is run.
//! Frames are 90 per second; a cube in a closed gripper moves with it, a released cube
//! drops onto what is below. The [`ExecutionReport`] says per step whether its effects
//! held (and if not, which, with the grounded facts), where hands and cubes ended, and
//! whether the goal holds in the final grounded state (as text: [`ExecutionReport::text`]); [`export`] writes the plan with
//! poses as JSON for robot execution frameworks (`docs/execution.md`).
//!
//! ```
//! let domain = pddl::parse_domain(
//!     "(define (domain d) (:requirements :strips :typing)
//!        (:types hand thing - object cube table - thing)
//!        (:predicates (handopen ?h - hand) (inhand ?h - hand ?x - thing)
//!                     (ontop ?x - thing ?y - thing) (intouch ?x - thing ?y - thing))
//!        (:action take :parameters (?h - hand ?c - cube)
//!          :precondition (handopen ?h)
//!          :effect (and (not (handopen ?h)) (inhand ?h ?c))))",
//! ).unwrap();
//! let problem = pddl::parse_problem(
//!     "(define (problem p) (:domain d)
//!        (:objects left_hand - hand cube_1 - cube table - table)
//!        (:init (handopen left_hand) (ontop cube_1 table))
//!        (:goal (inhand left_hand cube_1)))",
//! ).unwrap();
//! let plan = [pddl::Step::new("take", ["left_hand", "cube_1"])];
//! let report = cubeworld::execute(&domain, &problem, &plan).unwrap();
//! assert!(report.steps[0].ok());
//! assert!(report.goal.reached);
//! assert!(report.text().ends_with("ok\ngoal reached\n"), "{}", report.text());
//! ```

mod execute;
mod export;
pub mod geometry;
pub mod motion;
mod plan;
mod report_text;
mod symbolic;
pub mod world;

pub use execute::{
    execute, CubePose, ExecutionReport, FailedEffect, GoalReport, HandPose, StepReport,
};
pub use export::{export, EXPORT_FORMAT, EXPORT_VERSION};
pub use world::World;

/// An input the cube world cannot execute.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ExecuteError {
    /// The problem's scene: objects other than hands, cubes and a table, too many, or an
    /// initial state that cannot be laid out.
    #[error("{0}")]
    Scene(String),
    /// A step of the plan: an action the domain does not have, a wrong number of
    /// arguments, an unknown object, a type other than the five, a predicate outside
    /// Table 2.
    #[error("{0}")]
    Plan(String),
}
