//! The set-valued subcommands (the Boolean operations and `convert`), one generic path for all,
//! in 2D and 3D.

use super::args::{ReadOpts, WriteOpts};
use super::error::CliError;
use super::format::Format;
use super::input::one_stdin;
use super::output::write_bytes;
use super::progress;
use super::set::Set;
use crate::io::NumberStyle;
use std::path::Path;

/// A set-valued operation on one or more sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// A ∧ B.
    Meet,
    /// A ∨ B.
    Join,
    /// A′.
    Complement,
    /// A ∧ B′.
    Difference,
    /// (A ∧ B′) ∨ (A′ ∧ B).
    Xor,
    /// A itself (a change of format).
    Convert,
}

impl Op {
    /// The result on `sets`, which it consumes (binary operations fold left over those after
    /// the first); an error if there are none.
    pub fn apply<S: Set>(self, sets: Vec<S>) -> Result<S, CliError> {
        let mut sets = sets.into_iter();
        let Some(first) = sets.next() else {
            return Err(CliError::Usage("no input set given".to_string()));
        };
        let step: fn(&S, &S) -> Result<S, CliError> = match self {
            Op::Meet => S::meet,
            Op::Join => S::join,
            Op::Difference => S::difference,
            Op::Xor => S::symmetric_difference,
            Op::Complement => return Ok(S::complement(&first)),
            Op::Convert => return Ok(first),
        };
        sets.try_fold(first, |acc, s| step(&acc, &s))
    }
}

/// Read `inputs`, apply `op`, write the result as `write` says.
pub fn operate<S: Set>(
    op: Op,
    inputs: &[&Path],
    read: &ReadOpts,
    write: &WriteOpts,
    ctx: S::Ctx,
) -> Result<(), CliError> {
    one_stdin(inputs.iter().copied())?;
    let format = Format::of_output(write.output.as_deref(), write.to, S::DIMENSION)?;
    let sets = inputs
        .iter()
        .map(|p| S::load(p, read, ctx))
        .collect::<Result<Vec<_>, _>>()?;
    let vertices = sets.iter().map(S::size).sum();
    let message = || {
        format!(
            "{} of {vertices} vertices",
            format!("{op:?}").to_lowercase()
        )
    };
    let result = progress::while_working(message, vertices, || op.apply(sets))?;
    let style = if write.exact {
        NumberStyle::Exact
    } else {
        NumberStyle::Decimal
    };
    write_bytes(write.output.as_deref(), &result.encode(format, style)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::Point;
    use crate::num::Rational;
    use crate::yin2::YinSet2;

    fn square(x: i64, y: i64, s: i64) -> YinSet2<Rational> {
        let p = |a, b| Point::int(a, b);
        YinSet2::from_curves(vec![vec![
            p(x, y),
            p(x + s, y),
            p(x + s, y + s),
            p(x, y + s),
        ]])
        .unwrap()
    }

    #[test]
    fn each_op_is_the_kernel_operation() {
        let (a, b) = (square(0, 0, 2), square(1, 1, 2));
        let two = || vec![a.clone(), b.clone()];
        assert_eq!(Op::Meet.apply(two()).unwrap(), &a & &b);
        assert_eq!(Op::Join.apply(two()).unwrap(), &a | &b);
        assert_eq!(Op::Difference.apply(two()).unwrap(), &a - &b);
        assert_eq!(Op::Xor.apply(two()).unwrap(), &a ^ &b);
        assert_eq!(Op::Complement.apply(vec![a.clone()]).unwrap(), !&a);
        assert_eq!(Op::Convert.apply(vec![a.clone()]).unwrap(), a);
        let three = vec![a.clone(), b.clone(), square(0, 1, 2)];
        assert_eq!(
            Op::Meet.apply(three).unwrap(),
            &(&a & &b) & &square(0, 1, 2)
        );
        assert!(Op::Meet.apply(Vec::<YinSet2<Rational>>::new()).is_err());
    }
}
