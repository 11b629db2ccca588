//! Opening a page in headless Firefox from `file://` with the network off and reading what
//! it reports.
//!
//! Firefox's headless mode can take a screenshot (`--screenshot`) but not print the
//! document, so the page's self test (`#selftest`, the viewer's `viewer.js`) also logs its
//! results to the console as one line `gmap-selftest {…}`, which a fresh profile's
//! `devtools.console.stdout.content` sends to stdout. Uncaught errors of the page are the
//! `JavaScript error: file://…` lines Firefox writes to stderr.
//!
//! Headless Firefox finds no GL driver on a machine without a display; WebGL then runs on
//! Mesa's software rasterizer through EGL's surfaceless platform (`EGL_PLATFORM=surfaceless`,
//! `LIBGL_ALWAYS_SOFTWARE=1`, `MOZ_WEBGL_FORCE_EGL=1`, and the prefs `webgl.force-enabled`,
//! `gfx.x11-egl.force-enabled`). The network is off as for Chromium: `unshare -rn` where the
//! system allows it, and in any case a proxy on a closed port.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use crate::chromium::{find_browser, offline};
use std::time::{Duration, Instant};

/// The Firefox binary: `$GMAP_FIREFOX`, else `firefox` or `firefox-esr` on the `PATH`;
/// `None` (with a notice printed) when there is none.
pub fn firefox() -> Option<PathBuf> {
    find_browser("GMAP_FIREFOX", &["firefox", "firefox-esr"], "apt-get install firefox-esr")
}

/// What one run of a page reported.
pub struct Run {
    /// the page's self-test results
    pub selftest: serde_json::Value,
    /// the `JavaScript error` lines Firefox reported for the page (`file://` sources)
    pub page_errors: Vec<String>,
    /// the screenshot's size in bytes
    pub screenshot_bytes: u64,
    /// the whole browser run, start to exit
    pub wall: Duration,
    /// whether the browser ran in a network namespace without network
    pub isolated: bool,
}

/// The prefs of the fresh profile: the console on stdout, no first-run pages or
/// background requests, WebGL on the software rasterizer, every request through a proxy on
/// a closed port.
const USER_JS: &str = r#"user_pref("devtools.console.stdout.content", true);
user_pref("browser.shell.checkDefaultBrowser", false);
user_pref("datareporting.policy.dataSubmissionEnabled", false);
user_pref("toolkit.telemetry.reportingpolicy.firstRun", false);
user_pref("app.update.auto", false);
user_pref("webgl.force-enabled", true);
user_pref("gfx.x11-egl.force-enabled", true);
user_pref("network.proxy.type", 1);
user_pref("network.proxy.http", "127.0.0.1");
user_pref("network.proxy.http_port", 9);
user_pref("network.proxy.ssl", "127.0.0.1");
user_pref("network.proxy.ssl_port", 9);
user_pref("network.proxy.allow_hijacking_localhost", true);
"#;

/// Opens `page` with `#selftest` in headless Firefox (a fresh profile) and returns what it
/// reported. Panics (a test failure) when the page logged no results.
pub fn run_selftest(browser: &Path, page: &Path) -> Run {
    let tmp = tempfile::tempdir().unwrap();
    let profile = tmp.path().join("profile");
    std::fs::create_dir(&profile).unwrap();
    std::fs::write(profile.join("user.js"), USER_JS).unwrap();
    let shot = tmp.path().join("shot.png");
    let url = format!("file://{}#selftest", page.canonicalize().unwrap().display());
    let (mut cmd, isolated) = offline(browser);
    cmd.env("LIBGL_ALWAYS_SOFTWARE", "1").env("EGL_PLATFORM", "surfaceless").env("MOZ_WEBGL_FORCE_EGL", "1");
    cmd.arg("--headless").arg("--no-remote").arg("--profile").arg(&profile);
    cmd.args(["--window-size", "1200,800", "--screenshot"]).arg(&shot).arg(&url);
    let start = Instant::now();
    let out = cmd.output().expect("run firefox");
    let wall = start.elapsed();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    // `console.log: "gmap-selftest {…}"`: the logged text as a JSON string
    let line = stdout
        .lines()
        .find_map(|l| l.strip_prefix("console.log: ").filter(|s| s.contains("gmap-selftest ")))
        .unwrap_or_else(|| {
            panic!("{}: the page logged no self-test results\nstdout:\n{stdout}\nstderr:\n{stderr}", page.display())
        });
    let logged: String = serde_json::from_str(line).unwrap_or_else(|e| panic!("console line {line}: {e}"));
    let json = logged.strip_prefix("gmap-selftest ").expect("the prefix");
    let selftest = serde_json::from_str(json).unwrap_or_else(|e| panic!("self-test JSON: {e}: {json}"));
    let page_errors = stderr
        .lines()
        .filter(|l| (l.starts_with("JavaScript error") || l.contains("Uncaught")) && l.contains("file://"))
        .map(str::to_string)
        .collect();
    let screenshot_bytes = std::fs::metadata(&shot).map(|m| m.len()).unwrap_or(0);
    Run { selftest, page_errors, screenshot_bytes, wall, isolated }
}
