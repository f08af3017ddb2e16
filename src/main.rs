//! The `yinset` command. With no arguments (or `demo`) it runs the built-in demonstration; see
//! `yinset --help` and docs/cli.md for the subcommands.

use std::process::ExitCode;

fn main() -> ExitCode {
    yinset::cli::main()
}
