#!/usr/bin/env bash
# Keeps the history of the work out of the documents and the source comments, where it lives in
# git instead: fails, naming each file:line, where README.md, benches/BENCHMARKS.md,
# fuzz/README.md, proofs/README.md, Cargo.toml (it ships in the package) or a comment in
# src/**/*.rs has
#   * a commit hash: a word of 7 to 40 lower-case hex digits with a digit and a letter in it,
#     not a hex constant (0x…, #rrggbb…, part of a longer hex or decimal word) nor a number in
#     exponent notation past 7 characters (1e999999); hashes of digits alone pass;
#   * a date of work: an ISO year-month (2026-11, 2026-11-26) from 2020 on;
#   * the word "session";
#   * "issue N" (or "issues N").
# The files are the arguments, or the ones above (run from anywhere in the repository).
# BENCHMARKS.md may name the commits it measured in its header (before its first `## `
# section), and no commit below it.
set -euo pipefail
if [ "$#" -eq 0 ]; then
  cd "$(dirname "$0")/.."
  mapfile -t files < <(printf '%s\n' README.md benches/BENCHMARKS.md fuzz/README.md \
    proofs/README.md Cargo.toml; git ls-files 'src/*.rs')
  set -- "${files[@]}"
fi
exec perl -e '
use strict;
use warnings;
my $hash = qr/(?<![\w.#+-])(?=[0-9a-f]*[0-9])(?=[0-9a-f]*[a-f])(?![0-9]e[0-9]{6,}(?!\w))[0-9a-f]{7,40}(?![\w])/;
my @rules = (
  [ "a commit hash", $hash ],
  [ "a date of work", qr/\b20[2-9][0-9]-(?:0[1-9]|1[0-2])\b/ ],
  [ "the word \"session\"", qr/\bsessions?\b/i ],
  [ "an issue number", qr/\bissues? #?[0-9]+/i ],
);
my $found = 0;
for my $file (@ARGV) {
  open(my $fh, "<", $file) or die "no_history: cannot read $file: $!\n";
  my $rust = $file =~ /\.rs$/;
  # BENCHMARKS.md names the commits it measured in its header, above its first section.
  my $header = $file =~ /BENCHMARKS\.md$/;
  while (my $line = <$fh>) {
    my $text = $line;
    $header = 0 if $line =~ /^## /;
    if ($rust) {
      # Only comments: the text after the first //.
      next unless $text =~ s{^.*?//}{};
    }
    for my $rule (@rules) {
      my ($what, $re) = @$rule;
      while ($text =~ /($re)/g) {
        next if $header && $re == $hash;
        chomp(my $shown = $line);
        print "$file:$.: $what ($1): $shown\n";
        $found++;
      }
    }
  }
  close($fh);
}
if ($found) {
  print STDERR "no_history: $found mention(s) of the history of the work; it belongs in git\n";
  exit 1;
}
' "$@"
