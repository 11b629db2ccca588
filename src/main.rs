//! The `gmap` command. Each subcommand is a few lines over library calls; see `cli/`.

mod cli;

fn main() -> std::process::ExitCode {
    ignore_file_size_signal();
    cli::run()
}

/// Past a file-size limit (`ulimit -f`) the kernel sends SIGXFSZ, whose default action kills
/// the process before the atomic writer (`gmap_core::io::write_atomic`) can remove its
/// temporary file. Ignored, the signal turns into a failed write (EFBIG): the writer cleans
/// up and the command ends with `error: …` and exit code 1.
fn ignore_file_size_signal() {
    #[cfg(unix)]
    // SAFETY: called first thing in `main`, before any other thread exists; setting the
    // disposition of SIGXFSZ to SIG_IGN installs no handler code, so no async-signal-safety
    // requirement applies, and the only effect is that write(2) past the limit fails with
    // EFBIG instead of ending the process.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
}
