package io.concord.examples;

import io.concord.core.ArchitectureRules;
import org.junit.jupiter.api.Test;

/**
 * This module's main code keeps the architecture ({@link ArchitectureRules}); and since the
 * examples are a user's code, they reach no internal package of Concord's.
 */
class ArchitectureTest extends ArchitectureRules {

    @Test
    void aUsersCodeUsesNoInternalType() {
        usesNoInternals(main);
    }
}
