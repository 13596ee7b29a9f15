/* A ROS 2 peer on Eclipse Cyclone DDS (Debian's cyclonedds-dev), for mechsim's ROS 2 wire tests:
 * the DDS library under rmw_cyclonedds_cpp, with types compiled by Cyclone's idlc from IDL written
 * from the official ROS 2 message definitions (ros2_types.idl, ros2_graph.idl): nothing of
 * mechsim's own code. It subscribes and decodes, or publishes commands, as a ROS 2 node would, and
 * prints what it saw as JSON lines on stdout.
 *
 *   cyclone_peer_<distro> --domain D --seconds S
 *       [--sub TOPIC=KIND[:QOS]]...        KIND: clock tf tf_static joint_state laser image
 *                                          camera_info odometry imu string graph
 *                                          QOS: be, rel, tl (override the kind's ROS default), deep
 *                                          (reliable, keep last 1000: a rate measurement)
 *       [--pub TOPIC=KIND:VALUES]...       twist:vx,vy,vz,wx,wy,wz   twist_stamped:(same)
 *                                          float64_array:v1,v2,...   string:text
 *                                          trajectory:j1,j2,...:p1,p2,...:SECONDS
 *       [--rate HZ]                        publishing rate (default 20)
 *       [--save-image FILE.ppm]            the last image received, as a binary PPM
 *       [--endpoints]                      print the USER_DATA of every peer writer (type hashes)
 *       [--count-only]                     count samples without decoding them (a light
 *                                          subscriber for benchmarks)
 *       [--call SERVICE=empty|model_list]... call a std_srvs/srv/Empty (or gazebo_msgs/srv/GetModelList) service first, as an
 *                                          rmw_cyclonedds_cpp client does (header in the payload,
 *                                          "clientid=" USER_DATA); prints {"service":...,"reply":...}
 *                                          and only then subscribes and publishes
 *
 * Topics are ROS names ("/clock", "ros_discovery_info" as is); the peer adds rmw's "rt" prefix.
 * Each subscription prints its first 3 samples ({"topic":..., "n":..., "sample":{...}}) and, at
 * the end, {"topic":..., "summary":true, "count":N, "span":wall seconds first..last, "last":{...}}.
 * Discovery configuration comes from CYCLONEDDS_URI (the tests point it at a namespace's lo).
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "dds/dds.h"
#include "ros2_graph.h"
#include "ros2_services.h"
#include "ros2_types.h"

#define MAX_TOPICS 16
#define BATCH 16

typedef enum { K_CLOCK, K_TF, K_TF_STATIC, K_JOINT_STATE, K_LASER, K_IMAGE, K_CAMERA_INFO, K_ODOMETRY, K_IMU, K_STRING,
               K_GRAPH, K_TWIST, K_TWIST_STAMPED, K_FLOAT64_ARRAY, K_TRAJECTORY, K_UNKNOWN } kind_t;

static const struct { const char* name; kind_t kind; const dds_topic_descriptor_t* desc; } kinds[] = {
  {"clock", K_CLOCK, &rosgraph_msgs_msg_dds__Clock__desc},
  {"tf", K_TF, &tf2_msgs_msg_dds__TFMessage__desc},
  {"tf_static", K_TF_STATIC, &tf2_msgs_msg_dds__TFMessage__desc},
  {"joint_state", K_JOINT_STATE, &sensor_msgs_msg_dds__JointState__desc},
  {"laser", K_LASER, &sensor_msgs_msg_dds__LaserScan__desc},
  {"image", K_IMAGE, &sensor_msgs_msg_dds__Image__desc},
  {"camera_info", K_CAMERA_INFO, &sensor_msgs_msg_dds__CameraInfo__desc},
  {"odometry", K_ODOMETRY, &nav_msgs_msg_dds__Odometry__desc},
  {"imu", K_IMU, &sensor_msgs_msg_dds__Imu__desc},
  {"string", K_STRING, &std_msgs_msg_dds__String__desc},
  {"graph", K_GRAPH, &rmw_dds_common_msg_dds__ParticipantEntitiesInfo__desc},
  {"twist", K_TWIST, &geometry_msgs_msg_dds__Twist__desc},
  {"twist_stamped", K_TWIST_STAMPED, &geometry_msgs_msg_dds__TwistStamped__desc},
  {"float64_array", K_FLOAT64_ARRAY, &std_msgs_msg_dds__Float64MultiArray__desc},
  {"trajectory", K_TRAJECTORY, &trajectory_msgs_msg_dds__JointTrajectory__desc},
};

typedef struct {
  char topic[256];
  kind_t kind;
  dds_entity_t reader;
  long count;
  double first_wall, last_wall;
  char qos[8];  /* be, rel, tl: overrides the kind's ROS default */
  char children[4096];  /* tf: every child frame seen, as a JSON list's items */
  char* last;   /* the last sample as JSON (malloc'd) */
} sub_t;

typedef struct {
  char topic[256];
  kind_t kind;
  char values[1024];
  dds_entity_t writer;
  long sent;
} pub_t;

static double wall_now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static kind_t kind_of(const char* name, const dds_topic_descriptor_t** desc) {
  for (size_t i = 0; i < sizeof kinds / sizeof kinds[0]; ++i) {
    if (strcmp(kinds[i].name, name) == 0) {
      *desc = kinds[i].desc;
      return kinds[i].kind;
    }
  }
  return K_UNKNOWN;
}

/* ---- a small JSON builder */
typedef struct { char* text; size_t len, cap; } buf_t;
static void put(buf_t* b, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
static void put(buf_t* b, const char* fmt, ...) {
  va_list ap;
  for (;;) {
    va_start(ap, fmt);
    int n = vsnprintf(b->text ? b->text + b->len : NULL, b->text ? b->cap - b->len : 0, fmt, ap);
    va_end(ap);
    if (n < 0) return;
    if (b->text && b->len + (size_t)n < b->cap) {
      b->len += (size_t)n;
      return;
    }
    b->cap = (b->cap + (size_t)n + 256) * 2;
    b->text = realloc(b->text, b->cap);
    if (b->len == 0) b->text[0] = '\0';
  }
}
static void put_str(buf_t* b, const char* s) {
  put(b, "\"");
  for (; s && *s; ++s) {
    if (*s == '"' || *s == '\\') put(b, "\\%c", *s);
    else if ((unsigned char)*s < 0x20) put(b, "\\u%04x", (unsigned char)*s);
    else put(b, "%c", *s);
  }
  put(b, "\"");
}
static void put_num(buf_t* b, double v) {
  if (v != v) put(b, "\"nan\"");
  else if (v > 1e300 || v < -1e300) put(b, v > 0 ? "\"inf\"" : "\"-inf\"");
  else put(b, "%.9g", v);
}
static void put_time(buf_t* b, const builtin_interfaces_msg_dds__Time_* t) {
  put(b, "{\"sec\":%d,\"nanosec\":%u}", t->sec, t->nanosec);
}
static void put_header(buf_t* b, const std_msgs_msg_dds__Header_* h) {
  put(b, "\"stamp\":");
  put_time(b, &h->stamp);
  put(b, ",\"frame_id\":");
  put_str(b, h->frame_id);
}
static void put_doubles(buf_t* b, const double* v, size_t n) {
  put(b, "[");
  for (size_t i = 0; i < n; ++i) {
    if (i) put(b, ",");
    put_num(b, v[i]);
  }
  put(b, "]");
}

static const char* save_image_path = NULL;
static int count_only = 0;

/* The sample as JSON: what a test checks. */
static char* describe(kind_t kind, const void* sample) {
  buf_t b = {0};
  put(&b, "{");
  switch (kind) {
    case K_CLOCK: {
      const rosgraph_msgs_msg_dds__Clock_* m = sample;
      put(&b, "\"clock\":");
      put_time(&b, &m->clock);
      break;
    }
    case K_TF:
    case K_TF_STATIC: {
      const tf2_msgs_msg_dds__TFMessage_* m = sample;
      put(&b, "\"count\":%u,\"transforms\":[", m->transforms._length);
      for (uint32_t i = 0; i < m->transforms._length; ++i) {
        const geometry_msgs_msg_dds__TransformStamped_* t = &m->transforms._buffer[i];
        if (i) put(&b, ",");
        put(&b, "{");
        put_header(&b, &t->header);
        put(&b, ",\"child\":");
        put_str(&b, t->child_frame_id);
        put(&b, ",\"t\":");
        put_doubles(&b, &t->transform.translation.x, 3);
        put(&b, ",\"q\":");
        put_doubles(&b, &t->transform.rotation.x, 4);
        put(&b, "}");
      }
      put(&b, "]");
      break;
    }
    case K_JOINT_STATE: {
      const sensor_msgs_msg_dds__JointState_* m = sample;
      put_header(&b, &m->header);
      put(&b, ",\"name\":[");
      for (uint32_t i = 0; i < m->name._length; ++i) {
        if (i) put(&b, ",");
        put_str(&b, m->name._buffer[i]);
      }
      put(&b, "],\"position\":");
      put_doubles(&b, m->position._buffer, m->position._length);
      put(&b, ",\"velocity\":");
      put_doubles(&b, m->velocity._buffer, m->velocity._length);
      break;
    }
    case K_LASER: {
      const sensor_msgs_msg_dds__LaserScan_* m = sample;
      put_header(&b, &m->header);
      double lo = 1e30, hi = -1e30;
      uint32_t finite = 0;
      for (uint32_t i = 0; i < m->ranges._length; ++i) {
        const double r = m->ranges._buffer[i];
        if (r == r && r < 1e30 && r > -1e30) {
          ++finite;
          if (r < lo) lo = r;
          if (r > hi) hi = r;
        }
      }
      put(&b, ",\"angle_min\":");
      put_num(&b, m->angle_min);
      put(&b, ",\"angle_max\":");
      put_num(&b, m->angle_max);
      put(&b, ",\"angle_increment\":");
      put_num(&b, m->angle_increment);
      put(&b, ",\"range_min\":");
      put_num(&b, m->range_min);
      put(&b, ",\"range_max\":");
      put_num(&b, m->range_max);
      put(&b, ",\"ranges\":%u,\"finite\":%u,\"nearest\":", m->ranges._length, finite);
      put_num(&b, finite ? lo : -1);
      put(&b, ",\"farthest\":");
      put_num(&b, finite ? hi : -1);
      break;
    }
    case K_IMAGE: {
      const sensor_msgs_msg_dds__Image_* m = sample;
      put_header(&b, &m->header);
      double sum = 0;
      for (uint32_t i = 0; i < m->data._length; ++i) sum += m->data._buffer[i];
      put(&b, ",\"height\":%u,\"width\":%u,\"encoding\":", m->height, m->width);
      put_str(&b, m->encoding);
      put(&b, ",\"step\":%u,\"bytes\":%u,\"mean\":", m->step, m->data._length);
      put_num(&b, m->data._length ? sum / m->data._length : 0);
      if (save_image_path && strcmp(m->encoding, "rgb8") == 0 && m->data._length == (uint32_t)m->height * m->step) {
        FILE* f = fopen(save_image_path, "wb");
        if (f) {
          fprintf(f, "P6\n%u %u\n255\n", m->width, m->height);
          for (uint32_t row = 0; row < m->height; ++row) fwrite(m->data._buffer + row * m->step, 1, (size_t)m->width * 3, f);
          fclose(f);
        }
      }
      break;
    }
    case K_CAMERA_INFO: {
      const sensor_msgs_msg_dds__CameraInfo_* m = sample;
      put_header(&b, &m->header);
      put(&b, ",\"height\":%u,\"width\":%u,\"distortion_model\":", m->height, m->width);
      put_str(&b, m->distortion_model);
      put(&b, ",\"d\":");
      put_doubles(&b, m->d._buffer, m->d._length);
      put(&b, ",\"k\":");
      put_doubles(&b, m->k, 9);
      put(&b, ",\"p\":");
      put_doubles(&b, m->p, 12);
      break;
    }
    case K_ODOMETRY: {
      const nav_msgs_msg_dds__Odometry_* m = sample;
      put_header(&b, &m->header);
      put(&b, ",\"child_frame_id\":");
      put_str(&b, m->child_frame_id);
      put(&b, ",\"position\":");
      put_doubles(&b, &m->pose.pose.position.x, 3);
      put(&b, ",\"orientation\":");
      put_doubles(&b, &m->pose.pose.orientation.x, 4);
      put(&b, ",\"linear\":");
      put_doubles(&b, &m->twist.twist.linear.x, 3);
      put(&b, ",\"angular\":");
      put_doubles(&b, &m->twist.twist.angular.x, 3);
      break;
    }
    case K_IMU: {
      const sensor_msgs_msg_dds__Imu_* m = sample;
      put_header(&b, &m->header);
      put(&b, ",\"orientation\":");
      put_doubles(&b, &m->orientation.x, 4);
      put(&b, ",\"linear_acceleration\":");
      put_doubles(&b, &m->linear_acceleration.x, 3);
      break;
    }
    case K_STRING: {
      const std_msgs_msg_dds__String_* m = sample;
      put(&b, "\"length\":%zu,\"head\":", m->data ? strlen(m->data) : (size_t)0);
      char head[81] = {0};
      if (m->data) strncpy(head, m->data, 80);
      put_str(&b, head);
      break;
    }
    case K_GRAPH: {
      const rmw_dds_common_msg_dds__ParticipantEntitiesInfo_* m = sample;
      put(&b, "\"gid_size\":%d,\"gid\":\"", (int)sizeof m->gid.data);
      for (size_t i = 0; i < sizeof m->gid.data; ++i) put(&b, "%02x", m->gid.data[i]);
      put(&b, "\",\"nodes\":[");
      for (uint32_t i = 0; i < m->node_entities_info_seq._length; ++i) {
        const rmw_dds_common_msg_dds__NodeEntitiesInfo_* n = &m->node_entities_info_seq._buffer[i];
        if (i) put(&b, ",");
        put(&b, "{\"namespace\":");
        put_str(&b, n->node_namespace);
        put(&b, ",\"name\":");
        put_str(&b, n->node_name);
        put(&b, ",\"readers\":%u,\"writers\":%u}", n->reader_gid_seq._length, n->writer_gid_seq._length);
      }
      put(&b, "]");
      break;
    }
    default:
      break;
  }
  put(&b, "}");
  return b.text;
}

static dds_qos_t* qos_for(kind_t kind, const char* override) {
  dds_qos_t* q = dds_create_qos();
  dds_reliability_kind_t rel = DDS_RELIABILITY_RELIABLE;
  dds_durability_kind_t dur = DDS_DURABILITY_VOLATILE;
  int32_t depth = 10;
  switch (kind) {
    case K_CLOCK: rel = DDS_RELIABILITY_BEST_EFFORT; depth = 1; break;            /* rclcpp::ClockQoS */
    case K_TF: depth = 100; break;                                                 /* tf2_ros::DynamicListenerQoS */
    case K_TF_STATIC: dur = DDS_DURABILITY_TRANSIENT_LOCAL; depth = 100; break;    /* tf2_ros::StaticListenerQoS */
    case K_LASER: case K_IMAGE: case K_CAMERA_INFO: case K_IMU:
      rel = DDS_RELIABILITY_BEST_EFFORT; depth = 5; break;                         /* rclcpp::SensorDataQoS */
    case K_STRING: dur = DDS_DURABILITY_TRANSIENT_LOCAL; depth = 1; break;         /* robot_description */
    case K_GRAPH: dur = DDS_DURABILITY_TRANSIENT_LOCAL; depth = 1; break;
    default: break;
  }
  if (override) {
    if (strcmp(override, "be") == 0) rel = DDS_RELIABILITY_BEST_EFFORT;
    else if (strcmp(override, "rel") == 0) rel = DDS_RELIABILITY_RELIABLE;
    else if (strcmp(override, "tl") == 0) { rel = DDS_RELIABILITY_RELIABLE; dur = DDS_DURABILITY_TRANSIENT_LOCAL; }
    else if (strcmp(override, "deep") == 0) { rel = DDS_RELIABILITY_RELIABLE; depth = 1000; }  /* counts every sample */
  }
  dds_qset_reliability(q, rel, DDS_MSECS(100));
  dds_qset_durability(q, dur);
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, depth);
  return q;
}

static void dds_name(const char* topic, char* out, size_t size) {
  if (topic[0] == '/') snprintf(out, size, "rt%s", topic);
  else snprintf(out, size, "%s", topic);
}

/* Comma-separated doubles into v (at most max); returns the count. */
static int parse_doubles(const char* text, double* v, int max) {
  int n = 0;
  const char* p = text;
  while (*p && n < max) {
    char* end = NULL;
    v[n++] = strtod(p, &end);
    if (end == p) return n - 1;
    p = (*end == ',') ? end + 1 : end;
    if (*end != ',') break;
  }
  return n;
}

static void stamp_now(builtin_interfaces_msg_dds__Time_* t) {
  /* A command's stamp: 0 (rclcpp's "now" is the node's clock; controllers check its age against
   * their own sim time, and 0 = "as soon as possible" for trajectories). */
  t->sec = 0;
  t->nanosec = 0;
}

static void publish(pub_t* p) {
  double v[64];
  switch (p->kind) {
    case K_TWIST:
    case K_TWIST_STAMPED: {
      memset(v, 0, sizeof v);
      parse_doubles(p->values, v, 6);
      geometry_msgs_msg_dds__Twist_ t = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
      if (p->kind == K_TWIST) {
        dds_write(p->writer, &t);
      } else {
        geometry_msgs_msg_dds__TwistStamped_ s;
        memset(&s, 0, sizeof s);
        stamp_now(&s.header.stamp);
        s.header.frame_id = "base_link";
        s.twist = t;
        dds_write(p->writer, &s);
      }
      break;
    }
    case K_FLOAT64_ARRAY: {
      const int n = parse_doubles(p->values, v, 64);
      std_msgs_msg_dds__Float64MultiArray_ m;
      memset(&m, 0, sizeof m);
      m.data._length = m.data._maximum = (uint32_t)n;
      m.data._buffer = v;
      dds_write(p->writer, &m);
      break;
    }
    case K_STRING: {
      std_msgs_msg_dds__String_ m = {p->values};
      dds_write(p->writer, &m);
      break;
    }
    case K_TRAJECTORY: {
      /* joints:positions:seconds */
      char copy[1024];
      snprintf(copy, sizeof copy, "%s", p->values);
      char* joints = copy;
      char* positions = strchr(joints, ':');
      if (!positions) return;
      *positions++ = '\0';
      char* seconds = strchr(positions, ':');
      if (!seconds) return;
      *seconds++ = '\0';
      char* names[32];
      uint32_t count = 0;
      for (char* tok = strtok(joints, ","); tok && count < 32; tok = strtok(NULL, ",")) names[count++] = tok;
      const int n = parse_doubles(positions, v, 32);
      const double t = atof(seconds);
      trajectory_msgs_msg_dds__JointTrajectoryPoint_ point;
      memset(&point, 0, sizeof point);
      point.positions._length = point.positions._maximum = (uint32_t)n;
      point.positions._buffer = v;
      point.time_from_start.sec = (int32_t)t;
      point.time_from_start.nanosec = (uint32_t)((t - (int32_t)t) * 1e9);
      trajectory_msgs_msg_dds__JointTrajectory_ m;
      memset(&m, 0, sizeof m);
      stamp_now(&m.header.stamp);
      m.header.frame_id = "";
      m.joint_names._length = m.joint_names._maximum = count;
      m.joint_names._buffer = names;
      m.points._length = m.points._maximum = 1;
      m.points._buffer = &point;
      dds_write(p->writer, &m);
      break;
    }
    default:
      break;
  }
  ++p->sent;
}

/* tf: the child frames of every sample, each once (a test checks frames that are not in every
 * message: robot_state_publisher's and an odometry's go out separately). */
static void note_children(sub_t* s, const void* sample) {
  const tf2_msgs_msg_dds__TFMessage_* m = sample;
  for (uint32_t i = 0; i < m->transforms._length; ++i) {
    char quoted[300];
    snprintf(quoted, sizeof quoted, "\"%s\"", m->transforms._buffer[i].child_frame_id);
    if (strstr(s->children, quoted)) continue;
    const size_t used = strlen(s->children);
    if (used + strlen(quoted) + 2 >= sizeof s->children) return;
    snprintf(s->children + used, sizeof s->children - used, "%s%s", used ? "," : "", quoted);
  }
}

static void print_endpoints(dds_entity_t reader) {
  void* samples[BATCH] = {0};
  dds_sample_info_t infos[BATCH];
  int n;
  while ((n = dds_take(reader, samples, infos, BATCH, BATCH)) > 0) {
    for (int i = 0; i < n; ++i) {
      if (!infos[i].valid_data) continue;
      const dds_builtintopic_endpoint_t* e = samples[i];
      void* data = NULL;
      size_t size = 0;
      buf_t b = {0};
      put(&b, "{\"endpoint\":\"writer\",\"topic\":");
      put_str(&b, e->topic_name);
      put(&b, ",\"type\":");
      put_str(&b, e->type_name);
      put(&b, ",\"user_data\":");
      if (e->qos && dds_qget_userdata(e->qos, &data, &size) && data) {
        char text[512] = {0};
        memcpy(text, data, size < sizeof text - 1 ? size : sizeof text - 1);
        put_str(&b, text);
        dds_free(data);
      } else {
        put_str(&b, "");
      }
      put(&b, "}");
      printf("%s\n", b.text);
      free(b.text);
    }
    dds_return_loan(reader, samples, n);
  }
}

/* One call of a std_srvs/srv/Empty service in rmw_cyclonedds' form: waits (at most 5 s) until
 * the service is there (a matched request reader and reply writer), writes the request with its
 * header, waits (at most 3 s) for the reply carrying the same header. */
static void call_service(dds_entity_t pp, const char* service, int index, int model_list) {
  char rq[300], rr[300], user[64];
  snprintf(rq, sizeof rq, "rq%sRequest", service);
  snprintf(rr, sizeof rr, "rr%sReply", service);
  snprintf(user, sizeof user, "clientid=peer.%d.%d;", (int)getpid(), index);
  dds_qos_t* q = dds_create_qos();
  dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 10);
  dds_qset_userdata(q, user, strlen(user));
  const dds_entity_t wt = dds_create_topic(
      pp, model_list ? &gazebo_msgs_srv_dds__GetModelList_Request__desc : &std_srvs_srv_dds__Empty_Request__desc, rq, NULL, NULL);
  const dds_entity_t rt = dds_create_topic(
      pp, model_list ? &gazebo_msgs_srv_dds__GetModelList_Response__desc : &std_srvs_srv_dds__Empty_Response__desc, rr, NULL, NULL);
  const dds_entity_t w = dds_create_writer(pp, wt, q, NULL);
  const dds_entity_t r = dds_create_reader(pp, rt, q, NULL);
  dds_delete_qos(q);
  const double t0 = wall_now();
  int available = 0;
  while (!available && wall_now() - t0 < 5.0) {
    dds_publication_matched_status_t pm;
    dds_subscription_matched_status_t sm;
    dds_get_publication_matched_status(w, &pm);
    dds_get_subscription_matched_status(r, &sm);
    available = pm.current_count > 0 && sm.current_count > 0;
    struct timespec nap = {0, 5000000};
    if (!available) nanosleep(&nap, NULL);
  }
  /* Both requests are {client_id, seq, uint8}: one layout. */
  std_srvs_srv_dds__Empty_Request_ req;
  memset(&req, 0, sizeof req);
  dds_instance_handle_t ih = 0;
  dds_get_instance_handle(w, &ih);
  req.client_id = ih;
  req.seq = 1000 + index;
  const double t1 = wall_now();
  int replied = 0;
  char models[1024] = "";
  int success = 0;
  if (available) dds_write(w, &req);
  void* samples[BATCH] = {0};
  dds_sample_info_t infos[BATCH];
  while (available && !replied && wall_now() - t1 < 3.0) {
    int n = dds_take(r, samples, infos, BATCH, BATCH);
    for (int j = 0; j < n; ++j) {
      const std_srvs_srv_dds__Empty_Response_* rep = samples[j];
      if (infos[j].valid_data && rep->client_id == req.client_id && rep->seq == req.seq) {
        replied = 1;
        if (model_list) {
          const gazebo_msgs_srv_dds__GetModelList_Response_* m = samples[j];
          success = m->success;
          for (uint32_t k = 0; k < m->model_names._length; ++k) {
            const size_t used = strlen(models);
            snprintf(models + used, sizeof models - used, "%s\"%s\"", k ? "," : "", m->model_names._buffer[k]);
          }
        }
      }
    }
    if (n > 0) dds_return_loan(r, samples, n);
    struct timespec nap = {0, 1000000};
    nanosleep(&nap, NULL);
  }
  if (model_list) {
    printf("{\"service\":\"%s\",\"form\":\"rmw_cyclonedds\",\"available\":%s,\"reply\":%s,\"success\":%s,"
           "\"model_names\":[%s],\"ms\":%.1f}\n",
           service, available ? "true" : "false", replied ? "true" : "false", success ? "true" : "false", models,
           1e3 * (wall_now() - t1));
  } else {
    printf("{\"service\":\"%s\",\"form\":\"rmw_cyclonedds\",\"available\":%s,\"reply\":%s,\"ms\":%.1f}\n", service,
           available ? "true" : "false", replied ? "true" : "false", 1e3 * (wall_now() - t1));
  }
  dds_delete(r);
  dds_delete(w);
}

int main(int argc, char** argv) {
  int domain = 0;
  double seconds = 5.0, rate = 20.0;
  int endpoints = 0;
  sub_t subs[MAX_TOPICS];
  pub_t pubs[MAX_TOPICS];
  int nsubs = 0, npubs = 0, ncalls = 0;
  const char* calls[MAX_TOPICS];
  int call_kind[MAX_TOPICS] = {0};
  memset(subs, 0, sizeof subs);
  memset(pubs, 0, sizeof pubs);
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    const char* v = i + 1 < argc ? argv[i + 1] : NULL;
    if (strcmp(a, "--domain") == 0 && v) domain = atoi(argv[++i]);
    else if (strcmp(a, "--seconds") == 0 && v) seconds = atof(argv[++i]);
    else if (strcmp(a, "--rate") == 0 && v) rate = atof(argv[++i]);
    else if (strcmp(a, "--save-image") == 0 && v) save_image_path = argv[++i];
    else if (strcmp(a, "--endpoints") == 0) endpoints = 1;
    else if (strcmp(a, "--count-only") == 0) count_only = 1;
    else if (strcmp(a, "--call") == 0 && v && ncalls < MAX_TOPICS) {
      char* spec = argv[++i];
      char* eq = strchr(spec, '=');
      if (!eq || (strcmp(eq + 1, "empty") != 0 && strcmp(eq + 1, "model_list") != 0)) {
        fprintf(stderr, "cyclone_peer: --call SERVICE=empty|model_list\n");
        return 2;
      }
      call_kind[ncalls] = strcmp(eq + 1, "model_list") == 0;
      *eq = '\0';
      calls[ncalls++] = spec;
    }
    else if ((strcmp(a, "--sub") == 0 || strcmp(a, "--pub") == 0) && v && nsubs < MAX_TOPICS && npubs < MAX_TOPICS) {
      char spec[1400];
      snprintf(spec, sizeof spec, "%s", argv[++i]);
      char* eq = strchr(spec, '=');
      if (!eq) { fprintf(stderr, "cyclone_peer: '%s' is not TOPIC=KIND\n", spec); return 2; }
      *eq = '\0';
      char* kind = eq + 1;
      char* rest = strchr(kind, ':');
      if (rest) *rest++ = '\0';
      const dds_topic_descriptor_t* desc = NULL;
      const kind_t k = kind_of(kind, &desc);
      if (k == K_UNKNOWN) { fprintf(stderr, "cyclone_peer: unknown kind '%s'\n", kind); return 2; }
      if (a[2] == 's') {
        sub_t* s = &subs[nsubs++];
        snprintf(s->topic, sizeof s->topic, "%s", spec);
        s->kind = k;
        snprintf(s->qos, sizeof s->qos, "%s", rest ? rest : "");
      } else {
        pub_t* p = &pubs[npubs++];
        snprintf(p->topic, sizeof p->topic, "%s", spec);
        p->kind = k;
        snprintf(p->values, sizeof p->values, "%s", rest ? rest : "");
      }
    } else {
      fprintf(stderr, "cyclone_peer: unknown argument '%s'\n", a);
      return 2;
    }
  }
  setvbuf(stdout, NULL, _IOLBF, 0);
  dds_qos_t* pq = dds_create_qos();
  dds_qset_userdata(pq, "enclave=/;", strlen("enclave=/;"));
  const dds_entity_t pp = dds_create_participant((dds_domainid_t)domain, pq, NULL);
  dds_delete_qos(pq);
  if (pp < 0) { fprintf(stderr, "cyclone_peer: dds_create_participant: %s\n", dds_strretcode(-pp)); return 1; }
  for (int i = 0; i < ncalls; ++i) call_service(pp, calls[i], i, call_kind[i]);
  for (int i = 0; i < nsubs; ++i) {
    sub_t* s = &subs[i];
    const dds_topic_descriptor_t* desc = NULL;
    char dn[300];
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) if (kinds[k].kind == s->kind) desc = kinds[k].desc;
    dds_name(s->topic, dn, sizeof dn);
    const dds_entity_t topic = dds_create_topic(pp, desc, dn, NULL, NULL);
    dds_qos_t* q = qos_for(s->kind, s->qos[0] ? s->qos : NULL);
    s->reader = dds_create_reader(pp, topic, q, NULL);
    dds_delete_qos(q);
    if (s->reader < 0) { fprintf(stderr, "cyclone_peer: reader %s: %s\n", s->topic, dds_strretcode(-s->reader)); return 1; }
  }
  for (int i = 0; i < npubs; ++i) {
    pub_t* p = &pubs[i];
    const dds_topic_descriptor_t* desc = NULL;
    char dn[300];
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; ++k) if (kinds[k].kind == p->kind) desc = kinds[k].desc;
    dds_name(p->topic, dn, sizeof dn);
    const dds_entity_t topic = dds_create_topic(pp, desc, dn, NULL, NULL);
    dds_qos_t* q = dds_create_qos();  /* rclcpp's default publisher: reliable, volatile, keep last 10 */
    dds_qset_reliability(q, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_qset_history(q, DDS_HISTORY_KEEP_LAST, 10);
    p->writer = dds_create_writer(pp, topic, q, NULL);
    dds_delete_qos(q);
    if (p->writer < 0) { fprintf(stderr, "cyclone_peer: writer %s: %s\n", p->topic, dds_strretcode(-p->writer)); return 1; }
  }
  dds_entity_t builtin = 0;
  if (endpoints) builtin = dds_create_reader(pp, DDS_BUILTIN_TOPIC_DCPSPUBLICATION, NULL, NULL);

  const double start = wall_now();
  double next_pub = start;
  void* samples[BATCH] = {0};
  dds_sample_info_t infos[BATCH];
  while (wall_now() - start < seconds) {
    const double now = wall_now();
    for (int i = 0; i < npubs; ++i) {
      dds_publication_matched_status_t st;
      dds_get_publication_matched_status(pubs[i].writer, &st);
      if (st.current_count > 0 && now >= next_pub) publish(&pubs[i]);
    }
    if (now >= next_pub) next_pub = now + (rate > 0 ? 1.0 / rate : 0.05);
    for (int i = 0; i < nsubs; ++i) {
      sub_t* s = &subs[i];
      int n;
      while ((n = dds_take(s->reader, samples, infos, BATCH, BATCH)) > 0) {
        for (int j = 0; j < n; ++j) {
          if (!infos[j].valid_data) continue;
          const double t = wall_now();
          if (s->count == 0) s->first_wall = t;
          s->last_wall = t;
          ++s->count;
          /* Every sample decoded; the first 3 printed, the last kept for the summary. */
          if (count_only && s->count > 1) continue;
          if (s->kind == K_TF || s->kind == K_TF_STATIC) note_children(s, samples[j]);
          char* text = describe(s->kind, samples[j]);
          if (s->count <= 3) printf("{\"topic\":\"%s\",\"n\":%ld,\"sample\":%s}\n", s->topic, s->count, text);
          free(s->last);
          s->last = text;
        }
        dds_return_loan(s->reader, samples, n);
      }
    }
    if (endpoints) print_endpoints(builtin);
    struct timespec nap = {0, 1000000};
    nanosleep(&nap, NULL);
  }
  for (int i = 0; i < nsubs; ++i) {
    const sub_t* s = &subs[i];
    printf("{\"topic\":\"%s\",\"summary\":true,\"count\":%ld,\"span\":%.6f,\"children\":[%s],\"last\":%s}\n", s->topic,
           s->count, s->count > 1 ? s->last_wall - s->first_wall : 0.0, s->children, s->last ? s->last : "null");
  }
  for (int i = 0; i < npubs; ++i) printf("{\"topic\":\"%s\",\"published\":%ld}\n", pubs[i].topic, pubs[i].sent);
  dds_delete(pp);
  return 0;
}
