#!/bin/bash
# wetgran-movie: a movie with one frame per snapshot, of the width asked for, written under a
# temporary name and renamed; nothing left in /tmp; clear errors for a run without snapshots,
# a missing file and bad options, with no movie left behind.
set -u
run=${WG_BIN:?}/wetgran-run
movie=${WG_BIN}/wetgran-movie
scenes=$(cd "$(dirname "$0")/../sim/scenes" && pwd)
. "$(dirname "$0")/checks.sh"

check "--help names the options" bash -c "'$movie' --help | grep -q -- '--fps'"
"$run" "$scenes/shake2d.ini" n=300 lx=100 t_end=12 dt_snapshot=1 profile_start=0 dt_checkpoint=0 -q \
  -o "$tmp/run.h5" 2> /dev/null
scratch_before=$(ls -d /tmp/wetgran-movie.* 2> /dev/null | wc -l)
"$movie" "$tmp/run.h5" -o "$tmp/run.mp4" --width 640 --fps 5 -q; rc=$?
check "movie made (exit $rc)" test $rc -eq 0 -a -s "$tmp/run.mp4"
info=$(ffprobe -v error -count_frames -select_streams v:0 \
  -show_entries stream=nb_read_frames,width,codec_name -of csv=p=0 "$tmp/run.mp4")
check "one frame per snapshot (13), 640 wide, H.264: $info" test "$info" = "h264,640,13"
check "no temporary movie and no scratch frames left" \
  bash -c "[ ! -e '$tmp/run.mp4.tmp.mp4' ] && [ \$(ls -d /tmp/wetgran-movie.* 2> /dev/null | wc -l) -eq $scratch_before ]"
"$movie" "$tmp/run.h5" -o "$tmp/speed.mp4" --color speed --width 320 -q
check "coloured by speed" test -s "$tmp/speed.mp4"

"${WG_BIN}/wetgran-reduce" "$tmp/run.h5" -o "$tmp/nosnap.h5" --snapshots none 2> /dev/null
"$movie" "$tmp/nosnap.h5" -o "$tmp/nosnap.mp4" 2> "$tmp/err1"; rc=$?
check "a record without snapshots (wetgran-reduce --snapshots none): exit 1, says so, no movie" \
  bash -c "[ $rc -eq 1 ] && grep -q 'snapshot' '$tmp/err1' && [ ! -e '$tmp/nosnap.mp4' ]"
"$movie" "$tmp/none.h5" -o "$tmp/none.mp4" 2> "$tmp/err2"; rc=$?
check "a missing run file: non-zero exit, named" bash -c "[ $rc -ne 0 ] && grep -q none.h5 '$tmp/err2'"
"$movie" "$tmp/run.h5" -o "$tmp/x.mp4" --color red 2> "$tmp/err3"; rc=$?
check "a bad colour: exit 2, no movie" bash -c "[ $rc -eq 2 ] && [ ! -e '$tmp/x.mp4' ]"
"$movie" "$tmp/run.h5" 2> "$tmp/err4"; rc=$?
check "no -o: exit 2 with a message" bash -c "[ $rc -eq 2 ] && grep -q -- '-o' '$tmp/err4'"
summary
