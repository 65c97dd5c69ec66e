//! What the tests share, the integration tests and the crate's unit tests (`src/lib.rs`
//! includes this file under `cfg(test)`): a tiny well-formedness checker for the SVG and
//! HTML this crate writes, and runs and experiments written briefly.

#![allow(dead_code)] // each test binary uses its part

use report::{Experiment, Outcome, Planner, Run};

/// A run with no counts: `prio * 4` operators, search and total time `t`.
pub fn run(planner: Planner, prio: usize, goal: usize, outcome: Outcome, t: f64) -> Run {
    Run {
        planner,
        prio,
        operators: prio * 4,
        goal,
        outcome,
        search_time: t,
        total_time: t,
        times: vec![t],
        expansions: None,
        cost: None,
        length: None,
        executed: None,
    }
}

/// An experiment of `runs` and nothing else.
pub fn experiment(runs: Vec<Run>) -> Experiment {
    Experiment {
        runs,
        levels: vec![],
        goals: vec![],
        time_limit: 0.0,
        repeat: 0,
        seed: 0,
        machine: String::new(),
        versions: String::new(),
        notes: vec![],
        cubes: 0,
        hands: 0,
    }
}

/// Elements HTML writes without a closing tag.
const VOID: [&str; 6] = ["meta", "img", "br", "hr", "link", "input"];

/// Checks that tags are balanced and properly nested, attribute values are quoted,
/// and text holds no raw `<` and only known entities. `html`: void elements need no
/// closing tag. Returns the names of the elements opened, in order.
pub fn check_markup(text: &str, html: bool) -> Result<Vec<String>, String> {
    let mut stack: Vec<String> = Vec::new();
    let mut opened = Vec::new();
    let mut rest = text;
    let mut roots = 0;
    while let Some(lt) = rest.find('<') {
        check_text(&rest[..lt])?;
        let after = &rest[lt..];
        if after.starts_with("<?") {
            let end = after.find("?>").ok_or("unclosed <?")?;
            rest = &after[end + 2..];
            continue;
        }
        if after.starts_with("<!") {
            let end = after.find('>').ok_or("unclosed <!")?;
            rest = &after[end + 1..];
            continue;
        }
        let gt = tag_end(after)
            .ok_or_else(|| format!("unclosed tag at {:?}", &after[..after.len().min(40)]))?;
        let tag = &after[1..gt];
        rest = &after[gt + 1..];
        if let Some(name) = tag.strip_prefix('/') {
            let name = name.trim();
            match stack.pop() {
                Some(open) if open == name => {}
                other => return Err(format!("</{name}> closes {other:?}")),
            }
            continue;
        }
        let self_closing = tag.ends_with('/');
        let body = tag.trim_end_matches('/');
        let name: String = body
            .chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '-' || *c == ':')
            .collect();
        if name.is_empty() {
            return Err(format!("bad tag <{tag}>"));
        }
        check_attributes(&body[name.len()..])?;
        if stack.is_empty() {
            roots += 1;
        }
        opened.push(name.clone());
        if !(self_closing || (html && VOID.contains(&name.as_str()))) {
            stack.push(name);
        }
    }
    check_text(rest)?;
    if !stack.is_empty() {
        return Err(format!("unclosed elements {stack:?}"));
    }
    if roots != 1 {
        return Err(format!("{roots} root elements"));
    }
    Ok(opened)
}

/// The index of the `>` that ends the tag starting at 0, skipping quoted values.
fn tag_end(s: &str) -> Option<usize> {
    let mut quote = false;
    for (i, c) in s.char_indices() {
        match c {
            '"' => quote = !quote,
            '>' if !quote => return Some(i),
            '<' if !quote && i > 0 => return None,
            _ => {}
        }
    }
    None
}

fn check_attributes(s: &str) -> Result<(), String> {
    let mut rest = s.trim_start();
    while !rest.is_empty() {
        let eq = rest
            .find('=')
            .ok_or_else(|| format!("attribute without value: {rest:?}"))?;
        let name = rest[..eq].trim();
        if name.is_empty()
            || !name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == ':')
        {
            return Err(format!("bad attribute name {name:?}"));
        }
        let value = rest[eq + 1..]
            .strip_prefix('"')
            .ok_or_else(|| format!("unquoted value of {name}"))?;
        let close = value.find('"').ok_or("unterminated value")?;
        check_text(&value[..close])?;
        rest = value[close + 1..].trim_start();
    }
    Ok(())
}

fn check_text(s: &str) -> Result<(), String> {
    let mut rest = s;
    while let Some(amp) = rest.find('&') {
        let after = &rest[amp + 1..];
        let semi = after.find(';').ok_or("& without ;")?;
        let entity = &after[..semi];
        let known = [
            "amp", "lt", "gt", "quot", "apos", "ldquo", "rdquo", "ndash", "rarr",
        ];
        if !known.contains(&entity) && !entity.starts_with('#') {
            return Err(format!("unknown entity &{entity};"));
        }
        rest = &after[semi + 1..];
    }
    Ok(())
}

#[test]
fn the_checker_refuses_broken_markup() {
    assert!(check_markup("<a><b></b></a>", false).is_ok());
    assert!(check_markup("<a><b></a></b>", false).is_err());
    assert!(check_markup("<a><b></a>", false).is_err());
    assert!(check_markup("<a x=1></a>", false).is_err());
    assert!(check_markup("<a>&nope;</a>", false).is_err());
    assert!(check_markup("<a></a><b></b>", false).is_err());
    assert!(check_markup("<html><img src=\"x\"></html>", true).is_ok());
    assert!(check_markup("<html><img src=\"x\"></html>", false).is_err());
}
