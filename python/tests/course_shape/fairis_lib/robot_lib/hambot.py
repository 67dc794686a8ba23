"""A course-shaped robot class for the tests: a Supervisor made inside the constructor, the
scene's fields read as the course's library reads them, node strings in its format."""

import math
import types
import random
import xml.etree.ElementTree as ET

from controller import Supervisor

FROM_THE_FIXTURE = True


class HamBot(Supervisor):
    def __init__(self):
        self.experiment_supervisor = Supervisor()
        self.display = self.experiment_supervisor.getDevice('User Display')
        self.display.setOpacity(1.0)
        self.root_node = self.experiment_supervisor.getRoot()
        self.children_field = self.root_node.getField('children')
        self.robot_node = self.experiment_supervisor.getSelf()
        self.robot_translation_field = self.robot_node.getField('translation')
        self.robot_rotation_field = self.robot_node.getField('rotation')
        self.wheel_radius = .045
        self.timestep = int(self.experiment_supervisor.getBasicTimeStep())
        self.left_motor = self.experiment_supervisor.getDevice('left motor')
        self.right_motor = self.experiment_supervisor.getDevice('right motor')
        self.max_motor_velocity = self.left_motor.getMaxVelocity()
        for motor in (self.left_motor, self.right_motor):
            motor.setPosition(float('inf'))
            motor.setVelocity(0.0)
        self.left_encoder = self.experiment_supervisor.getDevice('left wheel encoder')
        self.left_encoder.enable(self.timestep)
        self.camera = self.experiment_supervisor.getDevice('camera')
        self.camera.enable(self.timestep)
        self.camera.recognitionEnable(self.timestep)
        self.lidar = self.experiment_supervisor.getDevice('lidar')
        self.lidar.enable(self.timestep)
        self.lidar.enablePointCloud()
        self.gps = self.experiment_supervisor.getDevice('gps')
        self.gps.enable(self.timestep)
        self.sensor_calibration()

    def sensor_calibration(self):
        while self.experiment_supervisor.step(self.timestep) != -1:
            break

    def set_velocities(self, left, right):
        self.left_motor.setVelocity(left)
        self.right_motor.setVelocity(right)

    def get_lidar_range_image(self):
        return self.lidar.getRangeImage()

    def load_environment(self, maze_file):
        root = ET.parse(maze_file).getroot()
        self.starts = [(float(p.get('x')), float(p.get('y')), float(p.get('theta')))
                       for p in root.find('startPositions').findall('pos')]
        # The course keeps its world's goals as maze.goal_locations, points with x and y.
        self.maze = types.SimpleNamespace(goal_locations=[
            types.SimpleNamespace(x=float(g.get('x')), y=float(g.get('y'))) for g in root.findall('goal')])
        for i, w in enumerate(root.findall('wall')):
            x1, y1, x2, y2 = (float(w.get(k)) for k in ('x1', 'y1', 'x2', 'y2'))
            length = math.dist((x1, y1), (x2, y2))
            theta = math.atan2(x1 - x2, y1 - y2)
            body = ('translation {:.2f} {:.2f} {:.2f} rotation {:.2f} {:.2f} {:.2f} {:.2f} '
                    'size {:.2f} {:.2f} {:.2f}').format((x1 + x2) / 2, (y1 + y2) / 2, 0.25, 0, 0, 1, theta,
                                                        0.012, length, 0.5)
            self.children_field.importMFNodeFromString(-1, 'DEF Obstacle_{} Obstacle '.format(i) + '{ ' + body + ' }')
        for i, m in enumerate(root.findall('landmark')):
            x, y, h = float(m.get('x')), float(m.get('y')), float(m.get('height'))
            rgb = [float(m.get(k)) for k in ('red', 'green', 'blue')]
            body = ('translation {:.2f} {:.2f} {:.2f} color {:.2f} {:.2f} {:.2f} '
                    'recognitionColors [{:.2f} {:.2f} {:.2f}] size {:.2f} {:.2f} {:.2f}').format(
                        x, y, h / 2, *rgb, *rgb, h, .25, .25 - .01)
            self.children_field.importMFNodeFromString(-1, 'DEF Landmark_{} Landmark '.format(i) + '{ ' + body + ' }')

    def teleport_robot(self, x=0.0, y=0.0, z=0.0, theta=math.pi / 3):
        self.robot_translation_field.setSFVec3f([x, y, z])
        self.robot_rotation_field.setSFRotation([0, 0, 1, theta])
        self.sensor_calibration()

    def move_to_start(self):
        self.starting_position = random.sample(self.starts, 1)[0]
        self.teleport_robot(self.starting_position[0], self.starting_position[1], theta=self.starting_position[2])
