//! `cagd check FILE...`: checks a teacher's own answers, written under `"expected"`.

use crate::args;
use crate::solve::{problems, read_json};
use crate::{CliError, Report};
use cagd_problem::check_with;
use cagd_problem::render::example_text;

/// The help of `cagd check`.
pub const HELP: &str = "\
Usage: cagd check FILE... [--lang en|es] [--max-degree N] [--max-points N] [--max-digits N]
                          [--max-depth N] [--max-exponent N]

Each FILE holds a problem or a JSON array of problems, each with the answer its author
expects under \"expected\" (same keys as the answer's result: surface, closed_form,
points...). Every problem is solved exactly and compared with it; where they differ, the
report says where, as `cagd examples` reports the errata of the notes. Exit code 1 if any
expected answer is wrong or missing. The limits and their flags are those of `cagd solve`
(docs/format.md, Limits).
";

/// Runs `cagd check`.
pub fn run(args: &[String]) -> Result<Report, CliError> {
    let mut allowed = vec!["--lang"];
    allowed.extend_from_slice(args::LIMIT_FLAGS);
    let o = args::parse(args, &allowed)?;
    if o.help {
        return Ok(HELP.to_string().into());
    }
    if o.positional.is_empty() {
        return Err(CliError::Usage("check needs at least one FILE".into()));
    }
    let (mut text, mut total, mut wrong) = (String::new(), 0usize, 0usize);
    for path in &o.positional {
        let doc = read_json(path)?;
        for (i, p) in problems(&doc).iter().enumerate() {
            total += 1;
            let mut v = check_with(p, &o.limits);
            if p.get("expected").is_none() {
                v.mismatches
                    .push("nothing to check: the problem has no \"expected\" answer".into());
            }
            if !v.passed() {
                wrong += 1;
            }
            text += &format!("-- {path} [{i}]\n");
            text += &example_text(&v, o.lang);
            text.push('\n');
        }
    }
    text += &format!(
        "{total} problems checked: {} correct, {wrong} wrong\n",
        total - wrong
    );
    Ok(Report {
        text,
        code: u8::from(wrong > 0),
    })
}
