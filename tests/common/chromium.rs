//! Opening a page in headless Chromium with the network off and reading what it reports.
//!
//! The page runs its self test when its address ends in `#selftest` (the viewer's
//! `viewer.js`) and writes the results as JSON into `<pre id="selftest">`; `--dump-dom`
//! prints the document after the load event, when the synchronous self test is done.
//! The browser runs without network: inside `unshare -rn` (a new network namespace with no
//! interface but loopback) when the system allows it, and in any case with every host
//! name resolving to nothing and a proxy on a closed port. Its network log
//! (`--log-net-log`) is read back to list every http(s) request the page made.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

/// The Chromium binary: `$GMAP_CHROMIUM`, else `chromium`, `chromium-browser` or
/// `google-chrome` found on the `PATH`; `None` (with a notice printed) when there is none.
pub fn chromium() -> Option<PathBuf> {
    find_browser("GMAP_CHROMIUM", &["chromium", "chromium-browser", "google-chrome"], "apt-get install chromium")
}

/// A browser binary: the path in the environment variable `var`, else the first of `names`
/// found on the `PATH`; `None`, with a notice naming `install`, when there is none.
pub fn find_browser(var: &str, names: &[&str], install: &str) -> Option<PathBuf> {
    if let Some(p) = std::env::var_os(var) {
        return Some(PathBuf::from(p));
    }
    let path = std::env::var_os("PATH").unwrap_or_default();
    for name in names {
        for dir in std::env::split_paths(&path) {
            let c = dir.join(name);
            if c.is_file() {
                return Some(c);
            }
        }
    }
    eprintln!("NOTICE: no {} on the PATH ({install}): the browser test is skipped", names[0]);
    None
}

/// What one run of a page reported.
pub struct Run {
    /// the page's self-test results
    pub selftest: serde_json::Value,
    /// http(s) requests made for the page, from the browser's network log
    pub page_requests: Vec<String>,
    /// console lines Chromium logged that report an uncaught error
    pub console_errors: Vec<String>,
    /// the whole browser run, start to exit
    pub wall: Duration,
    /// whether the browser ran in a network namespace without network
    pub isolated: bool,
}

/// The command that runs `browser` without network: inside `unshare -rn` where that works
/// (the second value), else as is.
pub fn offline(browser: &Path) -> (Command, bool) {
    if can_unshare() {
        let mut c = Command::new("unshare");
        c.arg("-rn").arg(browser);
        (c, true)
    } else {
        (Command::new(browser), false)
    }
}

/// Whether `unshare -rn` works here (a user and network namespace).
pub fn can_unshare() -> bool {
    Command::new("unshare").args(["-rn", "true"]).output().is_ok_and(|o| o.status.success())
}

/// Opens `page` with `#selftest` in headless Chromium and returns what it reported.
/// Panics (a test failure) when the browser fails or the page wrote no results.
pub fn run_selftest(browser: &Path, page: &Path) -> Run {
    let tmp = tempfile::tempdir().unwrap();
    let netlog = tmp.path().join("net.json");
    let url = format!("file://{}#selftest", page.canonicalize().unwrap().display());
    let args: Vec<String> = vec![
        "--headless".into(),
        "--no-sandbox".into(),
        "--disable-gpu".into(),
        "--disable-quic".into(),
        "--no-first-run".into(),
        "--disable-background-networking".into(),
        "--disable-component-update".into(),
        "--disable-sync".into(),
        format!("--user-data-dir={}", tmp.path().join("profile").display()),
        "--window-size=1200,800".into(),
        "--enable-logging=stderr".into(),
        "--v=0".into(),
        format!("--log-net-log={}", netlog.display()),
        "--proxy-server=127.0.0.1:9".into(),
        "--host-resolver-rules=MAP * ~NOTFOUND".into(),
        "--dump-dom".into(),
        url,
    ];
    let (mut cmd, isolated) = offline(browser);
    let start = Instant::now();
    let out = cmd.args(&args).output().expect("run chromium");
    let wall = start.elapsed();
    let dom = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    let results = dom
        .split("<pre id=\"selftest\">")
        .nth(1)
        .and_then(|s| s.split("</pre>").next())
        .unwrap_or_else(|| panic!("{}: the page wrote no self-test results\nstderr:\n{stderr}", page.display()));
    let text = results.replace("&lt;", "<").replace("&gt;", ">").replace("&quot;", "\"").replace("&amp;", "&");
    let selftest: serde_json::Value =
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("self-test JSON: {e}: {text}"));
    let console_errors =
        stderr.lines().filter(|l| l.contains("CONSOLE") && l.contains("Uncaught")).map(str::to_string).collect();
    Run { selftest, page_requests: page_requests(&netlog), console_errors, wall, isolated }
}

/// The http(s) addresses of the requests the page made (those whose site is `file://`) in a
/// Chromium network log; the browser's own background requests are left out.
pub fn page_requests(netlog: &Path) -> Vec<String> {
    let Ok(text) = std::fs::read_to_string(netlog) else { return Vec::new() };
    // a log cut short by the exit lacks its closing brackets
    let log: serde_json::Value = serde_json::from_str(&text)
        .or_else(|_| serde_json::from_str(&format!("{}]}}", text.trim_end().trim_end_matches(','))))
        .unwrap_or_else(|e| panic!("network log {}: {e}", netlog.display()));
    let mut out = Vec::new();
    for e in log["events"].as_array().into_iter().flatten() {
        let p = &e["params"];
        let url = p["url"].as_str().unwrap_or("");
        let from_page = p["site_for_cookies"].as_str().is_some_and(|s| s.contains("file://"))
            || p["network_isolation_key"].as_str().is_some_and(|s| s.starts_with("file://"));
        if (url.starts_with("http://") || url.starts_with("https://")) && from_page {
            out.push(url.to_string());
        }
    }
    out.sort();
    out.dedup();
    out
}
