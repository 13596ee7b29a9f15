#!/usr/bin/python3
"""One sensor_msgs/PointCloud2 from a running mechsim_node, drawn with gnuplot: what a ROS consumer
decodes (fields by name through sensor_msgs.point_cloud2), not the simulator's own buffers.

  scripts/ros_cloud_picture.py TOPIC OUT.png [--timeout S] [--every N]

Waits (at most --timeout s of wall time, default 60) for one message on TOPIC (subscribing is
what makes the camera render), keeps every N-th valid point (default 4) and draws them in the
camera's optical frame, seen from above and from the side, each in its own rgb colour. Run with Debian's
python3 (ROS_MASTER_URI as for rostopic)."""
import argparse
import os
import struct
import subprocess
import sys
import tempfile

import rospy
from sensor_msgs import point_cloud2
from sensor_msgs.msg import PointCloud2


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('topic')
    p.add_argument('out')
    p.add_argument('--timeout', type=float, default=60.0)
    p.add_argument('--every', type=int, default=4)
    a = p.parse_args()
    rospy.init_node('mechsim_cloud_picture', anonymous=True, disable_signals=True)
    try:
        msg = rospy.wait_for_message(a.topic, PointCloud2, timeout=a.timeout)
    except rospy.ROSException as e:
        sys.exit('ros_cloud_picture: no PointCloud2 on %s within %.0f s: %s' % (a.topic, a.timeout, e))
    names = [f.name for f in msg.fields]
    if not all(n in names for n in ('x', 'y', 'z', 'rgb')):
        sys.exit('ros_cloud_picture: %s has fields %s, not x y z rgb' % (a.topic, names))
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, 'cloud.dat')
        kept = 0
        with open(data, 'w') as f:
            for i, (x, y, z, rgb) in enumerate(point_cloud2.read_points(msg, ('x', 'y', 'z', 'rgb'), skip_nans=True)):
                if i % a.every:
                    continue
                packed = struct.unpack('<I', struct.pack('<f', rgb))[0]
                # Optical frame: x right, y down, z forward; drawn as x right, z ahead, -y up.
                f.write('%.4f %.4f %.4f %d\n' % (x, z, -y, packed & 0xffffff))
                kept += 1
        if kept == 0:
            sys.exit('ros_cloud_picture: every point of the cloud is NaN (nothing within the cutoffs)')
        script = '''set terminal pngcairo size 1400,620 background rgb "white" font ",11"
set output "%s"
set multiplot layout 1,2 title "%s (PointCloud2 %dx%d, fields %s), frame %s, t = %.3f s sim: %d points drawn" noenhanced
set key off
set grid
set size ratio -1
set title "from above"
set xlabel "x (m, right)"
set ylabel "z (m, ahead)"
plot "%s" using 1:2:4 with dots lc rgb variable
set title "from the side"
set xlabel "z (m, ahead)"
set ylabel "-y (m, up)"
plot "%s" using 2:3:4 with dots lc rgb variable
unset multiplot
''' % (a.out, a.topic, msg.width, msg.height, ' '.join(names), msg.header.frame_id, msg.header.stamp.to_sec(),
       kept, data, data)
        subprocess.run(['gnuplot'], input=script.encode(), check=True)
    print('%s: %d of %d points drawn -> %s' % (a.topic, kept, msg.width * msg.height, a.out))


if __name__ == '__main__':
    main()
