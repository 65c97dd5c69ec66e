//! The operator library under faults (issue 10, `docs/reliability.md`): learners killed
//! at any moment while they write, learners writing one library at once, a lock held for
//! too long. Drives the real `demoplan` executable.
//!
//! `DEMOPLAN_KILL_LOOP=N` sets the number of kills of the kill loop (default 60);
//! `DEMOPLAN_KILL_LOOP_SEED` its seed. It prints what it counted (run with
//! `--nocapture` to see it).

#![allow(clippy::unwrap_used, clippy::expect_used)] // tests fail loudly by design

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

mod common;
use common::{demoplan, simulated_study, tempdir};

/// Runs a command to its end; it must succeed.
fn run(cmd: &mut Command) {
    let out = cmd.output().unwrap();
    assert!(
        out.status.success(),
        "{cmd:?} failed: {}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The paper's simulated study (12 recordings of about 1 MB), made once.
fn study() -> &'static [PathBuf] {
    static STUDY: OnceLock<Vec<PathBuf>> = OnceLock::new();
    STUDY.get_or_init(|| simulated_study(&tempdir("study")))
}

/// A simulated session of `frames` frames (90 fps), written with the recording writer.
fn session(path: &Path, frames: u64) {
    let demo = simulate::session(&simulate::SimParams::default(), 7, frames).unwrap();
    let file = std::fs::File::create(path).unwrap();
    let mut out = recording::Writer::new(std::io::BufWriter::new(file), demo.header()).unwrap();
    let mut frame = recording::Frame::default();
    let mut truth = simulate::TruthFrame::default();
    let mut render = demo.frames();
    while render.next_into(&mut frame, &mut truth) {
        out.write_frame(&frame).unwrap();
    }
    out.finish().unwrap().flush().unwrap();
}

/// The temporary files of writers of `library` (`.NAME.demoplan-tmp-PID`).
fn temporaries(library: &Path) -> Vec<String> {
    let prefix = format!(
        ".{}.demoplan-tmp-",
        library.file_name().unwrap().to_string_lossy()
    );
    let mut found: Vec<String> = std::fs::read_dir(library.parent().unwrap())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(&prefix))
        .collect();
    found.sort();
    found
}

/// SplitMix64: the loop's delays, reproducible from a seed.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce5_e9b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in `0..=max`.
    fn duration(&mut self, max: Duration) -> Duration {
        let micros = max.as_micros().max(1) as u64;
        Duration::from_micros(self.next() % (micros + 1))
    }
}

fn env_number(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// A learner adding one recording to a big library (from a long session) is killed with
/// SIGKILL, again and again, at random moments: half the kills at a delay drawn from the
/// whole run, half once its temporary file has appeared, after a delay drawn from the
/// time a write takes. After each kill the library parses and holds exactly the old or
/// the new bytes. A temporary file left behind means the kill landed mid-write (after the
/// file was created, before the rename); the next learner to finish removes it.
#[test]
fn a_learner_killed_at_any_moment_leaves_the_old_or_the_new_library() {
    let kills = env_number("DEMOPLAN_KILL_LOOP", 60);
    let seed = env_number("DEMOPLAN_KILL_LOOP_SEED", 10);
    let dir = tempdir("kill-loop");
    let long = dir.join("session.jsonl");
    session(&long, 54_000); // 10 minutes at 90 fps: about 600 activities
    let library = dir.join("library.json");
    run(demoplan().arg("learn").arg(&long).arg("-o").arg(&library));
    let old = std::fs::read(&library).unwrap();
    let learner = || {
        let mut cmd = add_to(&library, &study()[..1]);
        cmd.stdout(Stdio::null()).stderr(Stdio::null());
        cmd
    };
    // Calibration: the new bytes, the time a whole run takes and the time its temporary
    // file exists (seen by polling).
    let (mut whole, mut write) = (Duration::ZERO, Duration::ZERO);
    let mut new = Vec::new();
    for _ in 0..3 {
        std::fs::write(&library, &old).unwrap();
        let start = Instant::now();
        let mut child = learner().spawn().unwrap();
        let tmp = dir.join(format!(".library.json.demoplan-tmp-{}", child.id()));
        let mut appeared = None;
        loop {
            let exists = tmp.exists();
            if exists && appeared.is_none() {
                appeared = Some(Instant::now());
            }
            if !exists && appeared.is_some() {
                break;
            }
            if child.try_wait().unwrap().is_some() {
                break;
            }
            std::thread::sleep(Duration::from_micros(50));
        }
        assert!(child.wait().unwrap().success());
        whole = whole.max(start.elapsed());
        if let Some(t) = appeared {
            write = write.max(t.elapsed());
        }
        new = std::fs::read(&library).unwrap();
    }
    assert_ne!(new, old);
    let write = write.max(Duration::from_micros(200));

    let mut rng = Rng(seed);
    let (mut before, mut mid_write, mut after, mut finished) = (0u64, 0u64, 0u64, 0u64);
    let mut most_temporaries = 0;
    for i in 0..kills {
        if std::fs::read(&library).unwrap() != old {
            std::fs::write(&library, &old).unwrap();
        }
        let mut child = learner().spawn().unwrap();
        if i % 2 == 0 {
            std::thread::sleep(rng.duration(whole));
        } else {
            let tmp = dir.join(format!(".library.json.demoplan-tmp-{}", child.id()));
            while !tmp.exists() && child.try_wait().unwrap().is_none() {
                std::thread::sleep(Duration::from_micros(20));
            }
            std::thread::sleep(rng.duration(write));
        }
        let _ = child.kill(); // SIGKILL; fails only when the learner has already ended
        let status = child.wait().unwrap();
        let bytes = std::fs::read(&library).unwrap();
        let text = String::from_utf8(bytes.clone()).unwrap();
        if let Err(e) = learn::Library::from_json(&text) {
            panic!("kill {i}: the library does not parse: {e:?}");
        }
        assert!(
            bytes == old || bytes == new,
            "kill {i}: the library is neither the old nor the new one"
        );
        let left = temporaries(&library);
        most_temporaries = most_temporaries.max(left.len());
        let own = format!(".library.json.demoplan-tmp-{}", child.id());
        if status.success() {
            finished += 1;
            assert_eq!(bytes, new);
            assert!(left.is_empty(), "a finished learner left {left:?}");
        } else if left.contains(&own) {
            mid_write += 1;
            assert_eq!(
                bytes, old,
                "kill {i}: renamed, yet its temporary file is there"
            );
        } else if bytes == new {
            after += 1;
        } else {
            before += 1;
        }
    }
    // One more learner finishes, and removes what the killed ones left.
    std::fs::write(&library, &old).unwrap();
    run(&mut learner());
    assert_eq!(std::fs::read(&library).unwrap(), new);
    assert_eq!(temporaries(&library), Vec::<String>::new());
    println!(
        "kill loop (seed {seed}): {kills} runs: {} killed ({before} before writing, \
         {mid_write} mid-write, {after} after the rename), {finished} finished first; \
         0 broken libraries; at most {most_temporaries} temporary file(s) left at once; \
         a run {:.1} ms, its temporary file seen for {:.2} ms",
        kills - finished,
        whole.as_secs_f64() * 1e3,
        write.as_secs_f64() * 1e3
    );
    // The delays are drawn so that some kills land mid-write; with few kills on a slow
    // machine none may, so this only asks for one in a long loop.
    if kills >= 200 {
        assert!(mid_write > 0, "no kill landed mid-write");
    }
}

/// Two learners adding different recordings to one library at once (`--library L -o L`)
/// lose no counts: the result is byte for byte the library learned from all recordings
/// in one batch. Several rounds, so that the learners overlap in different ways.
#[test]
fn concurrent_learners_of_one_library_lose_no_counts() {
    let files = study();
    let dir = tempdir("concurrent");
    let batch = dir.join("batch.json");
    run(demoplan().arg("learn").args(files).arg("-o").arg(&batch));
    let expected = std::fs::read(&batch).unwrap();
    let library = dir.join("library.json");
    for round in 0..4 {
        run(demoplan()
            .arg("learn")
            .arg(&files[0])
            .arg("-o")
            .arg(&library));
        // Odd rounds: one learner has much more to do than the other.
        let split = if round % 2 == 0 { 6 } else { 2 };
        let learners: Vec<_> = [&files[1..split], &files[split..]]
            .iter()
            .map(|part| {
                add_to(&library, part)
                    .args(["--lock-timeout", "infinity"])
                    .stdout(Stdio::null())
                    .stderr(Stdio::piped())
                    .spawn()
                    .unwrap()
            })
            .collect();
        for child in learners {
            let out = child.wait_with_output().unwrap();
            assert!(
                out.status.success(),
                "{}",
                String::from_utf8_lossy(&out.stderr)
            );
        }
        let got = std::fs::read(&library).unwrap();
        assert!(
            got == expected,
            "round {round}: the library differs from the batch's"
        );
    }
}

/// Holds the lock of `library` as a learner would, with this process's pid in it.
fn hold_lock(library: &Path) -> std::fs::File {
    let mut name = library.as_os_str().to_owned();
    name.push(".lock");
    let mut file = std::fs::OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(PathBuf::from(name))
        .unwrap();
    file.lock().unwrap();
    file.set_len(0).unwrap();
    writeln!(file, "{}", std::process::id()).unwrap();
    file
}

/// A lock held past `--lock-timeout` exits 75, names the lock file and its holder's pid,
/// and leaves the library as it was; a learner without a limit waits for the lock and
/// then writes.
#[test]
fn a_held_lock_makes_a_learner_wait_or_give_up() {
    let files = study();
    let dir = tempdir("held-lock");
    let library = dir.join("library.json");
    run(demoplan()
        .arg("learn")
        .arg(&files[0])
        .arg("-o")
        .arg(&library));
    let before = std::fs::read(&library).unwrap();
    let lock = hold_lock(&library);

    let out = add_to(&library, &files[1..2])
        .args(["--lock-timeout", "0.2s"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(75), "{stderr}");
    assert!(stderr.contains("library.json.lock"), "{stderr}");
    assert!(
        stderr.contains(&format!("pid {}", std::process::id())),
        "{stderr}"
    );
    assert_eq!(std::fs::read(&library).unwrap(), before);

    let mut waiting = add_to(&library, &files[1..2])
        .args(["--lock-timeout", "infinity"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    // It cannot finish while the lock is held: wait until it has segmented its recording
    // and waits for the lock (a while is enough; the check below holds either way).
    std::thread::sleep(Duration::from_millis(300));
    assert!(waiting.try_wait().unwrap().is_none());
    assert_eq!(std::fs::read(&library).unwrap(), before);
    drop(lock);
    assert!(waiting.wait().unwrap().success());
    let text = std::fs::read_to_string(&library).unwrap();
    let learned = learn::Library::from_json(&text).unwrap();
    assert_eq!(learned.recordings().count(), 2);
}

// ---------------------------------------------------------------------------------------
// Issue 23: the lock of a library by any of its names, lock files of other users, and
// writes that fail partway, injected from outside the process (a full tmpfs, a read-only
// mount, strace's fault injection and delays). They need root (mounts, another user,
// ptrace), which CI has; they do not skip.

/// A learner adding `files` to `library` (`--library L -o L`), its output captured.
fn add_to(library: &Path, files: &[PathBuf]) -> Command {
    let mut cmd = demoplan();
    cmd.arg("learn")
        .args(files)
        .arg("--library")
        .arg(library)
        .arg("-o")
        .arg(library);
    cmd
}

/// A library learned from the study's first recording, and the bytes it has once the
/// second is added (learned on a copy): the old and the new library of the fault tests.
fn old_and_new_library(dir: &Path) -> (PathBuf, Vec<u8>, Vec<u8>) {
    let library = dir.join("library.json");
    run(demoplan()
        .arg("learn")
        .arg(&study()[0])
        .arg("-o")
        .arg(&library));
    let old = std::fs::read(&library).unwrap();
    let copy = dir.join("copy.json");
    std::fs::write(&copy, &old).unwrap();
    run(&mut add_to(&copy, &study()[1..2]));
    let new = std::fs::read(&copy).unwrap();
    std::fs::remove_file(&copy).unwrap();
    let _ = std::fs::remove_file(dir.join("copy.json.lock"));
    assert_ne!(old, new);
    (library, old, new)
}

fn assert_root(what: &str) {
    // The effective uid, from the process's status file (no libc call needed).
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let euid = status
        .lines()
        .find_map(|l| l.strip_prefix("Uid:"))
        .and_then(|l| l.split_whitespace().nth(1))
        .unwrap();
    assert_eq!(
        euid, "0",
        "{what} needs root (mounts, another user, ptrace), as CI has; run the tests as root"
    );
}

/// Two names of one library, a symlink and a relative path, share one lock: while the
/// lock of the real file is held, a learner through the symlink and one through a
/// relative path both wait and give up (75); once it is released, a learner through the
/// symlink writes the real file, and the symlink stays a symlink.
#[test]
fn a_symlink_and_a_relative_path_to_a_library_share_its_lock() {
    let dir = tempdir("two-names");
    let real_dir = dir.join("real");
    std::fs::create_dir_all(&real_dir).unwrap();
    let (built, old, new) = old_and_new_library(&dir);
    let library = real_dir.join("library.json");
    std::fs::rename(&built, &library).unwrap();
    let link = dir.join("link.json");
    std::os::unix::fs::symlink(&library, &link).unwrap();

    let lock = hold_lock(&library);
    for (name, cwd) in [
        (link.clone(), dir.clone()),
        ("library.json".into(), real_dir.clone()),
    ] {
        let out = add_to(&name, &study()[1..2])
            .current_dir(&cwd)
            .args(["--lock-timeout", "0.2s"])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(75), "{}: {stderr}", name.display());
        assert!(stderr.contains("real/library.json.lock"), "{stderr}");
        assert_eq!(std::fs::read(&library).unwrap(), old);
    }
    drop(lock);
    run(&mut add_to(&link, &study()[1..2]));
    assert_eq!(std::fs::read(&library).unwrap(), new);
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert!(!dir.join("link.json.lock").exists());
}

/// A lock file created by a learner gets the library's permission bits, and the library
/// keeps its own when it is rewritten: a group-writable library stays lockable and
/// writable by its group.
#[test]
fn the_lock_file_gets_the_library_permission_bits() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempdir("lock-mode");
    let (library, _, new) = old_and_new_library(&dir);
    let _ = std::fs::remove_file(dir.join("library.json.lock"));
    std::fs::set_permissions(&library, std::fs::Permissions::from_mode(0o664)).unwrap();
    run(&mut add_to(&library, &study()[1..2]));
    assert_eq!(std::fs::read(&library).unwrap(), new);
    let mode = |p: &Path| std::fs::metadata(p).unwrap().permissions().mode() & 0o7777;
    assert_eq!(mode(&dir.join("library.json.lock")), 0o664);
    assert_eq!(mode(&library), 0o664);
}

/// A learner that may write the library but not its lock file (another user created
/// it, mode 0644) still takes the lock (`flock` on a read-only descriptor) and writes.
/// The learner runs as `nobody` (uid 65534) on a library and folder it owns.
#[test]
fn a_learner_takes_a_lock_file_another_user_created() {
    use std::os::unix::fs::PermissionsExt;
    use std::os::unix::process::CommandExt;
    assert_root("a_learner_takes_a_lock_file_another_user_created");
    let dir = tempdir("other-user");
    let (library, _, new) = old_and_new_library(&dir);
    let lock = dir.join("library.json.lock");
    std::fs::write(&lock, "1\n").unwrap(); // root's, 0644
    std::fs::set_permissions(&lock, std::fs::Permissions::from_mode(0o644)).unwrap();
    std::os::unix::fs::chown(&dir, Some(65534), Some(65534)).unwrap();
    std::os::unix::fs::chown(&library, Some(65534), Some(65534)).unwrap();
    let out = add_to(&library, &study()[1..2])
        .uid(65534)
        .gid(65534)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    assert_eq!(std::fs::read(&library).unwrap(), new);
    let owner = |p: &Path| std::os::unix::fs::MetadataExt::uid(&std::fs::metadata(p).unwrap());
    assert_eq!(owner(&lock), 0, "the lock file is still root's");
    assert_eq!(owner(&library), 65534);
}

/// Runs `script` in a private mount namespace (`unshare --mount`), so that what it
/// mounts vanishes with it, and returns its output. `DEMOPLAN`, `DIR` and `RECORDING`
/// are set for it.
fn in_mount_namespace(dir: &Path, script: &str) -> std::process::Output {
    Command::new("unshare")
        .args(["--mount", "--propagation", "private", "sh", "-euc", script])
        .env("DEMOPLAN", env!("CARGO_BIN_EXE_demoplan"))
        .env("DIR", dir)
        .env("RECORDING", &study()[1])
        .env("NO_COLOR", "1")
        .output()
        .expect("unshare (util-linux) runs")
}

/// What a failed write left, read back from the files the scripts copy out: the
/// learner's exit code and standard error, the library, the folder's names.
struct Aftermath {
    code: i32,
    stderr: String,
    library: Vec<u8>,
    names: Vec<String>,
}

impl Aftermath {
    /// The learner could not write: exit 35, a message giving `reason` and saying the
    /// library is unchanged, and the `old` library in place.
    #[track_caller]
    fn assert_write_refused(&self, reason: &str, old: &[u8]) {
        assert_eq!(self.code, 35, "{}", self.stderr);
        assert!(self.stderr.contains(reason), "{}", self.stderr);
        assert!(self.stderr.contains("it is unchanged"), "{}", self.stderr);
        assert!(self.library == old, "the library changed");
    }
}

fn aftermath(dir: &Path, script_output: &std::process::Output) -> Aftermath {
    let out = dir.join("out");
    let read = |name: &str| {
        std::fs::read(out.join(name)).unwrap_or_else(|e| {
            panic!(
                "{name} not copied out ({e}); the script said:\n{}",
                String::from_utf8_lossy(&script_output.stderr)
            )
        })
    };
    let mut names: Vec<String> = String::from_utf8(read("names"))
        .unwrap()
        .lines()
        .map(str::to_string)
        .collect();
    names.sort();
    Aftermath {
        code: String::from_utf8(read("code"))
            .unwrap()
            .trim()
            .parse()
            .unwrap(),
        stderr: String::from_utf8(read("stderr")).unwrap(),
        library: read("library.json"),
        names,
    }
}

/// The scripts' common part: a small tmpfs `disk` holding the library and its lock
/// file (as a previous learner left them); `$1` is run between the setup and the
/// learner; the learner's code, stderr, the library and the folder's names are copied
/// to `out`.
fn disk_script(size: &str, between: &str) -> String {
    format!(
        r#"
mkdir -p "$DIR/disk" "$DIR/out"
mount -t tmpfs -o size={size} demoplan-test "$DIR/disk"
cp "$DIR/library.json" "$DIR/disk/library.json"
echo 1 > "$DIR/disk/library.json.lock"
{between}
set +e
"$DEMOPLAN" learn "$RECORDING" --library "$DIR/disk/library.json" -o "$DIR/disk/library.json" \
    >/dev/null 2>"$DIR/out/stderr"
echo $? > "$DIR/out/code"
set -e
cp "$DIR/disk/library.json" "$DIR/out/library.json"
ls -A "$DIR/disk" > "$DIR/out/names"
"#
    )
}

/// A full disk (a tmpfs filled up): the write fails, the learner says why (exit 35,
/// "No space left on device", the library unchanged), the old library is intact and no
/// temporary file is left.
#[test]
fn a_full_disk_leaves_the_old_library_and_says_why() {
    assert_root("a_full_disk_leaves_the_old_library_and_says_why");
    let dir = tempdir("full-disk");
    let (_, old, _) = old_and_new_library(&dir);
    let script = disk_script(
        "1m",
        r#"cat /dev/zero > "$DIR/disk/filler" 2>/dev/null || true"#,
    );
    let output = in_mount_namespace(&dir, &script);
    let after = aftermath(&dir, &output);
    after.assert_write_refused("No space left on device", &old);
    assert!(after.stderr.contains("library.json"), "{}", after.stderr);
    assert_eq!(after.names, ["filler", "library.json", "library.json.lock"]);
    println!(
        "fault: full disk (tmpfs of 1 MiB, filled): exit 35, {}",
        first_line(&after.stderr)
    );
}

/// A read-only folder (the tmpfs remounted read-only; root ignores `chmod`): the lock
/// is taken on the read-only lock file, the write fails, the learner says why (exit
/// 35, "Read-only file system"), the library is intact.
#[test]
fn a_read_only_folder_leaves_the_old_library_and_says_why() {
    assert_root("a_read_only_folder_leaves_the_old_library_and_says_why");
    let dir = tempdir("read-only");
    let (_, old, _) = old_and_new_library(&dir);
    let script = disk_script("8m", r#"mount -o remount,ro "$DIR/disk""#);
    let output = in_mount_namespace(&dir, &script);
    let after = aftermath(&dir, &output);
    after.assert_write_refused("Read-only file system", &old);
    assert_eq!(after.names, ["library.json", "library.json.lock"]);
    println!(
        "fault: read-only folder (tmpfs remounted ro): exit 35, {}",
        first_line(&after.stderr)
    );
}

/// The first line of a message, for the summaries CI prints.
fn first_line(text: &str) -> &str {
    text.lines().next().unwrap_or("")
}

/// `strace` with `args` before the learner of `library`.
fn under_strace(args: &[&str], library: &Path) -> Command {
    let mut cmd = Command::new("strace");
    cmd.args(["-f", "-qq", "-o", "/dev/null"])
        .args(args)
        .arg(env!("CARGO_BIN_EXE_demoplan"))
        .arg("learn")
        .arg(&study()[1])
        .arg("--library")
        .arg(library)
        .arg("-o")
        .arg(library)
        .env("NO_COLOR", "1");
    cmd
}

/// An I/O error while the library is made durable (strace makes `fsync` fail with
/// EIO): the learner says why (exit 35, "Input/output error"), the old library is
/// intact and the temporary file is gone.
#[test]
fn an_io_error_leaves_the_old_library_and_says_why() {
    let dir = tempdir("io-error");
    let (library, old, _) = old_and_new_library(&dir);
    let out = under_strace(
        &["-e", "trace=fsync", "-e", "inject=fsync:error=EIO"],
        &library,
    )
    .output()
    .expect("strace runs (Debian package strace)");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(35), "{stderr}");
    assert!(stderr.contains("Input/output error"), "{stderr}");
    assert!(stderr.contains("it is unchanged"), "{stderr}");
    assert!(
        std::fs::read(&library).unwrap() == old,
        "the library changed"
    );
    assert_eq!(temporaries(&library), Vec::<String>::new());
    println!(
        "fault: I/O error (strace: fsync fails with EIO): exit 35, {}",
        first_line(&stderr)
    );
}

/// Whether process `pid` is stopped in a rename system call (`/proc/PID/syscall` starts
/// with its number).
fn in_rename(pid: u32) -> bool {
    let numbers: &[&str] = if cfg!(target_arch = "x86_64") {
        &["82", "264", "316"] // rename, renameat, renameat2
    } else {
        &["38", "276"] // renameat, renameat2 (aarch64 and other generic tables)
    };
    std::fs::read_to_string(format!("/proc/{pid}/syscall"))
        .ok()
        .and_then(|s| s.split_whitespace().next().map(str::to_string))
        .is_some_and(|n| numbers.contains(&n.as_str()))
}

/// A kill guaranteed to land mid-write: strace holds the learner at the entry of its
/// rename (its new library written in full to the temporary file) for a minute, the
/// test sees it there and kills it (SIGKILL). The library is byte for byte the old one,
/// the temporary file is what is left; the next learner writes the new library and
/// removes the temporary file.
#[test]
fn a_learner_killed_at_its_rename_leaves_the_old_library() {
    let dir = tempdir("killed-at-rename");
    let (library, old, new) = old_and_new_library(&dir);
    let mut strace = under_strace(
        &[
            "-e",
            "trace=rename,renameat,renameat2",
            "-e",
            "inject=rename,renameat,renameat2:delay_enter=60s",
        ],
        &library,
    )
    .stdout(Stdio::null())
    .stderr(Stdio::null())
    .spawn()
    .expect("strace runs (Debian package strace)");
    let start = Instant::now();
    let learner = loop {
        let found = temporaries(&library).into_iter().find_map(|name| {
            let pid: u32 = name.rsplit('-').next()?.parse().ok()?;
            in_rename(pid).then_some((pid, name))
        });
        if let Some(found) = found {
            break found;
        }
        assert!(
            strace.try_wait().unwrap().is_none(),
            "the learner ended before its rename"
        );
        assert!(start.elapsed() < Duration::from_secs(50), "no rename seen");
        std::thread::sleep(Duration::from_millis(5));
    };
    let (pid, name) = learner;
    let held = start.elapsed();
    assert_eq!(
        std::fs::read(dir.join(&name)).unwrap(),
        new,
        "written in full"
    );
    let killed = Command::new("kill")
        .args(["-KILL", &pid.to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    // A traced process stays stopped until its tracer lets it go: strace would hold it
    // for the rest of the delay. Killing strace detaches it, and the pending SIGKILL
    // ends it before the rename runs (the kernel skips a system call entered with a
    // fatal signal pending).
    strace.kill().unwrap();
    let status = strace.wait().unwrap();
    assert!(!status.success(), "strace was killed: {status}");
    while std::fs::metadata(format!("/proc/{pid}/syscall")).is_ok()
        && !std::fs::read_to_string(format!("/proc/{pid}/stat"))
            .unwrap_or_default()
            .contains(") Z")
    {
        std::thread::sleep(Duration::from_millis(5));
    }
    assert!(
        std::fs::read(&library).unwrap() == old,
        "the library changed"
    );
    assert_eq!(temporaries(&library), vec![name]);
    let text = std::fs::read_to_string(&library).unwrap();
    assert!(learn::Library::from_json(&text).is_ok());

    run(&mut add_to(&library, &study()[1..2]));
    assert!(std::fs::read(&library).unwrap() == new);
    assert_eq!(temporaries(&library), Vec::<String>::new());
    println!(
        "fault: killed while strace held its rename (seen there {:.2} s after its start): \
         the old library intact, its temporary file left, removed by the next learner",
        held.as_secs_f64()
    );
}
