"""ROS 2 (Humble) message definitions, as MCAP ``ros2msg`` schemas carry them.

A schema is the type's own definition followed by those of the types it uses, each after
a line of ``=`` and ``MSG: pkg/Type``, as rosbag2 writes them. Readers such as Foxglove and
rosbags decode messages from these texts alone. tests/simulate checks them against an
independent copy of the ROS interface definitions.
"""

from __future__ import annotations

_SEPARATOR = "=" * 80 + "\n"

# Each type's own fields, once.
_FIELDS: dict[str, str] = {
    "sensor_msgs/msg/LaserScan": (
        'std_msgs/Header header\n'
        'float32 angle_min\n'
        'float32 angle_max\n'
        'float32 angle_increment\n'
        'float32 time_increment\n'
        'float32 scan_time\n'
        'float32 range_min\n'
        'float32 range_max\n'
        'float32[] ranges\n'
        'float32[] intensities\n'
    ),
    "std_msgs/Header": (
        'builtin_interfaces/Time stamp\n'
        'string frame_id\n'
    ),
    "builtin_interfaces/Time": (
        'int32 sec\n'
        'uint32 nanosec\n'
    ),
    "sensor_msgs/msg/Imu": (
        'std_msgs/Header header\n'
        'geometry_msgs/Quaternion orientation\n'
        'float64[9] orientation_covariance\n'
        'geometry_msgs/Vector3 angular_velocity\n'
        'float64[9] angular_velocity_covariance\n'
        'geometry_msgs/Vector3 linear_acceleration\n'
        'float64[9] linear_acceleration_covariance\n'
    ),
    "geometry_msgs/Quaternion": (
        'float64 x\n'
        'float64 y\n'
        'float64 z\n'
        'float64 w\n'
    ),
    "geometry_msgs/Vector3": (
        'float64 x\n'
        'float64 y\n'
        'float64 z\n'
    ),
    "nav_msgs/msg/Odometry": (
        'std_msgs/Header header\n'
        'string child_frame_id\n'
        'geometry_msgs/PoseWithCovariance pose\n'
        'geometry_msgs/TwistWithCovariance twist\n'
    ),
    "geometry_msgs/PoseWithCovariance": (
        'geometry_msgs/Pose pose\n'
        'float64[36] covariance\n'
    ),
    "geometry_msgs/Pose": (
        'geometry_msgs/Point position\n'
        'geometry_msgs/Quaternion orientation\n'
    ),
    "geometry_msgs/Point": (
        'float64 x\n'
        'float64 y\n'
        'float64 z\n'
    ),
    "geometry_msgs/TwistWithCovariance": (
        'geometry_msgs/Twist twist\n'
        'float64[36] covariance\n'
    ),
    "geometry_msgs/Twist": (
        'geometry_msgs/Vector3 linear\n'
        'geometry_msgs/Vector3 angular\n'
    ),
    "sensor_msgs/msg/JointState": (
        'std_msgs/Header header\n'
        'string[] name\n'
        'float64[] position\n'
        'float64[] velocity\n'
        'float64[] effort\n'
    ),
    "sensor_msgs/msg/CameraInfo": (
        'std_msgs/Header header\n'
        'uint32 height\n'
        'uint32 width\n'
        'string distortion_model\n'
        'float64[] d\n'
        'float64[9] k\n'
        'float64[9] r\n'
        'float64[12] p\n'
        'uint32 binning_x\n'
        'uint32 binning_y\n'
        'sensor_msgs/RegionOfInterest roi\n'
    ),
    "sensor_msgs/msg/Image": (
        'std_msgs/Header header\n'
        'uint32 height\n'
        'uint32 width\n'
        'string encoding\n'
        'uint8 is_bigendian\n'
        'uint32 step\n'
        'uint8[] data\n'
    ),
    "sensor_msgs/RegionOfInterest": (
        'uint32 x_offset\n'
        'uint32 y_offset\n'
        'uint32 height\n'
        'uint32 width\n'
        'bool do_rectify\n'
    ),
    "tf2_msgs/msg/TFMessage": (
        'geometry_msgs/TransformStamped[] transforms\n'
    ),
    "geometry_msgs/TransformStamped": (
        'std_msgs/Header header\n'
        'string child_frame_id\n'
        'geometry_msgs/Transform transform\n'
    ),
    "geometry_msgs/Transform": (
        'geometry_msgs/Vector3 translation\n'
        'geometry_msgs/Quaternion rotation\n'
    ),
    "rosgraph_msgs/msg/Clock": (
        'builtin_interfaces/Time clock\n'
    ),
    "std_msgs/msg/String": (
        'string data\n'
    ),
    "sensor_msgs/msg/Range": (
        'uint8 ULTRASOUND=0\n'
        'uint8 INFRARED=1\n'
        'std_msgs/Header header\n'
        'uint8 radiation_type\n'
        'float32 field_of_view\n'
        'float32 min_range\n'
        'float32 max_range\n'
        'float32 range\n'
    ),
    "sensor_msgs/msg/PointCloud2": (
        'std_msgs/Header header\n'
        'uint32 height\n'
        'uint32 width\n'
        'sensor_msgs/PointField[] fields\n'
        'bool is_bigendian\n'
        'uint32 point_step\n'
        'uint32 row_step\n'
        'uint8[] data\n'
        'bool is_dense\n'
    ),
    "sensor_msgs/PointField": "".join(
        f"uint8 {name}={code}\n" for code, name in enumerate(
            ("INT8", "UINT8", "INT16", "UINT16", "INT32", "UINT32", "FLOAT32", "FLOAT64"), 1))
    + 'string name\nuint32 offset\nuint8 datatype\nuint32 count\n',
    "sensor_msgs/msg/PointCloud": (
        'std_msgs/Header header\n'
        'geometry_msgs/Point32[] points\n'
        'sensor_msgs/ChannelFloat32[] channels\n'
    ),
    "geometry_msgs/Point32": (
        'float32 x\n'
        'float32 y\n'
        'float32 z\n'
    ),
    "sensor_msgs/ChannelFloat32": (
        'string name\n'
        'float32[] values\n'
    ),
}

# The types each published type uses, in the order rosbag2 lists them.
_USES: dict[str, tuple[str, ...]] = {
    "sensor_msgs/msg/LaserScan": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
    ),
    "sensor_msgs/msg/Imu": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
        "geometry_msgs/Quaternion",
        "geometry_msgs/Vector3",
    ),
    "nav_msgs/msg/Odometry": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
        "geometry_msgs/PoseWithCovariance",
        "geometry_msgs/Pose",
        "geometry_msgs/Point",
        "geometry_msgs/Quaternion",
        "geometry_msgs/TwistWithCovariance",
        "geometry_msgs/Twist",
        "geometry_msgs/Vector3",
    ),
    "sensor_msgs/msg/JointState": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
    ),
    "sensor_msgs/msg/CameraInfo": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
        "sensor_msgs/RegionOfInterest",
    ),
    "sensor_msgs/msg/Image": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
    ),
    "tf2_msgs/msg/TFMessage": (
        "geometry_msgs/TransformStamped",
        "std_msgs/Header",
        "builtin_interfaces/Time",
        "geometry_msgs/Transform",
        "geometry_msgs/Vector3",
        "geometry_msgs/Quaternion",
    ),
    "rosgraph_msgs/msg/Clock": (
        "builtin_interfaces/Time",
    ),
    "std_msgs/msg/String": (),
    "sensor_msgs/msg/Range": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
    ),
    "sensor_msgs/msg/PointCloud2": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
        "sensor_msgs/PointField",
    ),
    "sensor_msgs/msg/PointCloud": (
        "std_msgs/Header",
        "builtin_interfaces/Time",
        "geometry_msgs/Point32",
        "sensor_msgs/ChannelFloat32",
    ),
}


def _schema(name: str) -> str:
    return _FIELDS[name] + "".join(
        f"{_SEPARATOR}MSG: {dep}\n{_FIELDS[dep]}" for dep in _USES[name])


MESSAGE_DEFINITIONS: dict[str, str] = {name: _schema(name) for name in _USES}
