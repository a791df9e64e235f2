package io.concord.console;

import io.concord.core.ArchitectureRules;

/**
 * This module's main code keeps the architecture ({@link ArchitectureRules}): no cycle between its
 * packages, and no type of an internal package in its API. Every module has this test.
 */
class ArchitectureTest extends ArchitectureRules {
}
