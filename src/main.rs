//! The `yinset` command. With no arguments (or `demo`) it runs the built-in demonstration.

use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.first().map(String::as_str) {
        None | Some("demo") => match yinset::demo::run() {
            Ok(report) => {
                print!("{report}");
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("yinset: {e}");
                ExitCode::FAILURE
            }
        },
        Some("-h" | "--help") => {
            println!("usage: yinset [demo]\n\nRuns the Boolean operations of the 2D Yin-set kernel on built-in example shapes\nin exact rational arithmetic and prints each result with its Betti numbers.");
            ExitCode::SUCCESS
        }
        Some(other) => {
            eprintln!("yinset: unknown subcommand `{other}` (try `yinset --help`)");
            ExitCode::from(2)
        }
    }
}
