//! Run fuzz inputs through a target's check without libFuzzer (for debugging a crash, and for
//! printing the decoded input):
//!
//! ```sh
//! cargo run --manifest-path fuzz/Cargo.toml --example replay -- TARGET FILE...
//! ```
use yinset_fuzz::input::{decode, ConstructInput, OpsInput};
use yinset_fuzz::input3::{Construct3Input, Ops3Input};
use yinset_fuzz::{check, check3, check3_float, text};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some((target, files)) = args.split_first() else {
        eprintln!("usage: replay TARGET FILE...");
        std::process::exit(2);
    };
    for file in files {
        let data = std::fs::read(file).unwrap_or_else(|e| panic!("{file}: {e}"));
        eprintln!("== {file}");
        match target.as_str() {
            "ops_exact" | "ops_float" => {
                let input: OpsInput = decode(&data).expect("decodes");
                eprintln!("{input:?}");
                if target == "ops_exact" {
                    check::ops_exact(&input);
                } else {
                    check::ops_float(&input);
                }
            }
            "construct" => {
                let input: ConstructInput = decode(&data).expect("decodes");
                eprintln!("{input:?}");
                check::construct(&input);
            }
            "parse_yin2" => text::yin2(&text::text_of(&data)),
            "parse_wkt" => text::wkt(&text::text_of(&data)),
            "parse_geojson" => text::geojson(&text::text_of(&data)),
            "ops3_exact" | "ops3_float" => {
                let input: Ops3Input = decode(&data).expect("decodes");
                eprintln!("{input:?}");
                if target == "ops3_exact" {
                    check3::ops3_exact(&input);
                } else {
                    check3_float::ops3_float(&input);
                }
            }
            "construct3" => {
                let input: Construct3Input = decode(&data).expect("decodes");
                eprintln!("{input:?}");
                check3::construct3(&input);
            }
            "parse_obj" => check3::obj(&text::text_of(&data)),
            other => panic!("unknown target {other}"),
        }
        eprintln!("ok");
    }
}
