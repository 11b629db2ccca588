//! The `gmap` command. Each subcommand is a few lines over library calls; see `cli/`.

mod cli;

fn main() -> std::process::ExitCode {
    cli::run()
}
