#!/bin/sh
# The jam as a film: every frame of a 3D drill-flute run drawn by flute_picture.py
# (coolant blue, chips red, barrier grey, seen perpendicular to the flute) into
# OUT_FRAMES/frame_NNNN.png, then joined by ffmpeg (Debian: ffmpeg) into an H.264 video.
#   flute_video.sh RUN/VARIANT VIDEO.mp4 [FRAMES_PER_SECOND (default 5)]
# The PNG frame series stays beside the video, in VIDEO_frames/.
set -e
[ $# -ge 2 ] || { sed -n '2,6p' "$0" >&2; exit 2; }
run=$1
video=$2
fps=${3:-5}
here=$(cd "$(dirname "$0")" && pwd)
command -v ffmpeg > /dev/null || { echo "flute_video.sh: needs ffmpeg (apt-get install ffmpeg)" >&2; exit 2; }
[ -d "$run/particles" ] || { echo "flute_video.sh: $run/particles: no frames" >&2; exit 2; }
frames=${video%.*}_frames
rm -rf "$frames"
mkdir -p "$frames"
n=0
for f in "$run"/particles/frame_*.h5; do
  number=$(basename "$f" .h5 | sed 's/^frame_0*//')
  python3 "$here/flute_picture.py" "$run" "$frames/$(printf 'frame_%04d.png' "$n")" "${number:-0}" > /dev/null
  n=$((n + 1))
done
# yuv420p and even sizes: the H.264 stream that every player opens.
ffmpeg -loglevel error -y -framerate "$fps" -i "$frames/frame_%04d.png" \
  -vf "scale=trunc(iw/2)*2:trunc(ih/2)*2" -c:v libx264 -pix_fmt yuv420p "$video.tmp.mp4"
mv "$video.tmp.mp4" "$video"
echo "wrote $video ($n frames at $fps per second; the PNG series in $frames/)"
