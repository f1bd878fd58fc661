#!/usr/bin/env bash
# The core's layering: derive the import graph among carry-core's top-level modules
# (`core/src/X.rs` and `core/src/X/`), or among the modules of any crate's module directory
# (`lab/src/fit`: its `crate::fit::X` paths name the sibling X, other `crate::` paths lie
# outside it), from their `crate::` and crossing `super::` paths
# (grouped `use crate::{a, b::c}` included, and names the crate root re-exports resolved to
# their module; comments and `#[cfg(test)]` modules left out),
# print it, and fail on any import circle, printing each one.
#
#   bash .ci/core-layers.sh [core/src]      # prints the graph; exit 1 on a circle
#   bash .ci/core-layers.sh lab/src/fit     # one module directory of a crate
set -euo pipefail
cd "$(dirname "$0")/.."
src="${1:-core/src}"
exec perl -e '
use strict; use warnings;
my $src = shift;
# A module directory below a crate root: its path from the root (`fit`, `fit::sub`).
my ($inner) = $src =~ m{/src/(.+?)/?$};
$inner =~ s{/}{::}g if defined $inner;
my %edges;                                    # from => { to => 1 }
my @files = split /\n/, `find "$src" -name "*.rs" | sort`;
for my $file (@files) {
    (my $rel = $file) =~ s{^\Q$src\E/}{};
    next if $rel eq "lib.rs" || $rel eq "mod.rs";
    my @path = split m{/}, $rel;
    $path[-1] =~ s/\.rs$//;
    pop @path if $path[-1] eq "mod";
    my $top = $path[0];
    $edges{$top} //= {};
    open my $fh, "<", $file or die "$file: $!";
    local $/; my $text = <$fh>; close $fh;
    # Strip comments (line and block) and string literals, keeping offsets irrelevant.
    $text =~ s{/\*.*?\*/}{ }gs;
    $text =~ s{"(?:\\.|[^"\\])*"}{""}gs;
    $text =~ s{//[^\n]*}{}g;
    if (defined $inner) {                    # crate::fit::X -> X; other crate:: paths leave
        (my $re = $inner) =~ s/::/\\s*::\\s*/g;
        $text =~ s/\bcrate\s*::\s*$re\s*::\s*/HERE::/g;
        $text =~ s/\bcrate\s*::/OUTSIDE::/g;
        $text =~ s/\bHERE::/crate::/g;
    }
    # Inline modules: [start, end, name, is_test].
    my @mods;
    while ($text =~ /((#\[cfg\(test\)\]\s*)?(?:pub(?:\([^)]*\))?\s+)?mod\s+(\w+)\s*\{)/g) {
        my ($start, $name, $test) = ($-[0], $3, defined $2);
        my $depth = 1; my $i = pos($text);
        while ($depth > 0 && $i < length $text) {
            my $c = substr($text, $i++, 1);
            $depth++ if $c eq "{"; $depth-- if $c eq "}";
        }
        push @mods, [$start, $i, $name, $test];
    }
    my $context = sub {                         # module path and test-ness at offset p
        my $p = shift; my @m = @path; my $test = 0;
        for my $m (sort { $a->[0] <=> $b->[0] } @mods) {
            next unless $m->[0] <= $p && $p < $m->[1];
            push @m, $m->[2]; $test ||= $m->[3];
        }
        return (\@m, $test);
    };
    my $add = sub { my $to = shift; $edges{$top}{$to} = 1 if $to ne $top; };
    # crate::X and crate::{X, Y::..}
    while ($text =~ /\bcrate\s*::\s*(\{|\w+)/g) {
        my ($p, $what) = ($-[0], $1);
        my (undef, $test) = $context->($p); next if $test;
        if ($what ne "{") { $add->($what); next; }
        my $depth = 1; my $i = pos($text); my $group = "";
        while ($depth > 0 && $i < length $text) {
            my $c = substr($text, $i++, 1);
            $depth++ if $c eq "{"; $depth-- if $c eq "}";
            $group .= $depth == 1 ? $c : ($c eq "," ? ";" : $c);
        }
        for my $item (split /,/, $group) {
            $add->($1) if $item =~ /^\s*(\w+)/ && $1 ne "self";
        }
    }
    # super::super::...::X that climbs out of the top-level module
    while ($text =~ /\b((?:super\s*::\s*)+)(\{|\w+)/g) {
        my ($p, $supers, $what) = ($-[0], $1, $2);
        my ($m, $test) = $context->($p); next if $test;
        my $n = () = $supers =~ /super/g;
        next if $n < @$m;                        # stays inside the top-level module
        if ($what ne "{") { $add->($what); next; }
        my $depth = 1; my $i = pos($text); my $group = "";
        while ($depth > 0 && $i < length $text) {
            my $c = substr($text, $i++, 1);
            $depth++ if $c eq "{"; $depth-- if $c eq "}";
            $group .= $depth == 1 ? $c : ($c eq "," ? ";" : $c);
        }
        for my $item (split /,/, $group) { $add->($1) if $item =~ /^\s*(\w+)/; }
    }
}
# Names the crate root re-exports (`pub use scene::{Scene, ..}` in lib.rs) stand for their
# module; other names that are not modules (e.g. a macro) are dropped.
my %root;
if (open my $lib, "<", "$src/lib.rs") {
    local $/; my $t = <$lib>; close $lib;
    $t =~ s{//[^\n]*}{}g;
    while ($t =~ /pub\s+use\s+(\w+)\s*::\s*(\{[^}]*\}|\w+)/g) {
        my ($m, $names) = ($1, $2);
        $root{$_} = $m for grep { length } map { s/\s+as\s+\w+//r =~ s/\W//gr } split /,/, $names;
    }
}
for my $f (keys %edges) {
    for my $t (keys %{$edges{$f}}) {
        next if exists $edges{$t};
        delete $edges{$f}{$t};
        $edges{$f}{$root{$t}} = 1 if exists $root{$t} && $root{$t} ne $f && exists $edges{$root{$t}};
    }
}
# Tarjan SCC.
my ($index, %idx, %low, %on, @stack, @sccs) = (0);
my $strong; $strong = sub {
    my $v = shift; $idx{$v} = $low{$v} = $index++; push @stack, $v; $on{$v} = 1;
    for my $w (sort keys %{$edges{$v}}) {
        if (!exists $idx{$w}) { $strong->($w); $low{$v} = $low{$w} if $low{$w} < $low{$v}; }
        elsif ($on{$w}) { $low{$v} = $idx{$w} if $idx{$w} < $low{$v}; }
    }
    if ($low{$v} == $idx{$v}) {
        my @c; my $w; do { $w = pop @stack; $on{$w} = 0; push @c, $w; } while ($w ne $v);
        push @sccs, [sort @c] if @c > 1;
    }
};
for my $v (sort keys %edges) { $strong->($v) unless exists $idx{$v}; }
# Layers (longest path to a leaf) when acyclic.
print "core modules and what they import (crate:: / super:: paths, tests left out):\n";
my %layer; my $depth; $depth = sub {
    my ($v, $seen) = @_; return $layer{$v} if exists $layer{$v};
    return 0 if $seen->{$v}; local $seen->{$v} = 1;
    my $d = 0; for my $w (sort keys %{$edges{$v}}) { my $x = 1 + $depth->($w, $seen); $d = $x if $x > $d; }
    return $layer{$v} = $d;
};
$depth->($_, {}) for sort keys %edges;
for my $v (sort { $layer{$a} <=> $layer{$b} or $a cmp $b } keys %edges) {
    printf "  L%-2d %-11s -> %s\n", $layer{$v}, $v, join(", ", sort keys %{$edges{$v}}) || "(leaf)";
}
if (!@sccs) { print "no import circle among ", scalar(keys %edges), " top-level modules\n"; exit 0; }
for my $c (@sccs) {
    my %in = map { $_ => 1 } @$c;
    # One concrete circle through the first member (BFS back to it).
    my $s = $c->[0]; my %prev; my @q = ($s); my $found;
    BFS: while (@q) { my $v = shift @q;
        for my $w (sort keys %{$edges{$v}}) { next unless $in{$w};
            if ($w eq $s) { $prev{"END"} = $v; $found = 1; last BFS; }
            next if exists $prev{$w}; $prev{$w} = $v; push @q, $w; } }
    my @path = ($s); my $v = $prev{"END"};
    while ($v ne $s) { unshift @path, $v; $v = $prev{$v}; } unshift @path, $s;
    print "IMPORT CIRCLE among {", join(", ", @$c), "}: ", join(" -> ", @path), "\n";
}
exit 1;
' "$src"
