//! `zeitner-fuzz`: see the library's documentation, or `--help`.

use clap::Parser;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    zeitner_fuzz::command::run(zeitner_fuzz::command::FuzzArgs::parse())
}
