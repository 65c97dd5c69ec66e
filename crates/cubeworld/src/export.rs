//! The plan with object poses per step, as JSON for robot execution frameworks
//! (`docs/execution.md` has the schema).

use serde_json::{json, Value};

use crate::execute::ExecutionReport;
use crate::world::{CUBE_SIZE, FRAME_RATE, TABLE_DEPTH, TABLE_HEIGHT, TABLE_WIDTH, TABLE_X};

/// The `format` field of the export.
pub const EXPORT_FORMAT: &str = "demoplan-execution";
/// Its `version` field.
pub const EXPORT_VERSION: u32 = 1;

/// The export of an execution: format and version, the scene, the initial poses, per
/// step the action, its arguments, type, hand, start and end time, gripper command,
/// motion primitives, the check, and the end poses of hands and cubes; the goal check.
pub fn export(report: &ExecutionReport) -> Value {
    let table = report
        .recording
        .header
        .entities
        .iter()
        .find(|e| e.kind == recording::EntityKind::Table)
        .map(|e| e.name.clone())
        .unwrap_or_default();
    let steps: Vec<Value> = report
        .steps
        .iter()
        .map(|s| {
            json!({
                "index": s.index,
                "action": s.name,
                "arguments": s.arguments,
                "type": s.kind.operator_name(),
                "hand": s.hand,
                "start": s.start,
                "end": s.end,
                "gripper": s.gripper,
                "primitives": s.primitives,
                "ok": s.ok(),
                "failed": s.failed,
                "collisions": s.collisions,
                "hands": s.hands,
                "cubes": s.cubes,
            })
        })
        .collect();
    json!({
        "format": EXPORT_FORMAT,
        "version": EXPORT_VERSION,
        "domain": report.domain,
        "problem": report.problem,
        "frame": "REP 103: metres, seconds, x forward, y left, z up; quaternions (x, y, z, w)",
        "frame_rate": FRAME_RATE,
        "scene": {
            "table": {
                "name": table,
                "centre": [TABLE_X, 0.0, 0.5 * TABLE_HEIGHT],
                "size": [TABLE_DEPTH, TABLE_WIDTH, TABLE_HEIGHT],
            },
            "cube_size": CUBE_SIZE,
        },
        "initial": {
            "hands": report.initial_hands,
            "cubes": report.initial_cubes,
        },
        "steps": steps,
        "goal": report.goal,
        "success": report.success(),
    })
}
