package io.concord.layers;

import io.concord.core.layer.Layer;
import io.concord.core.layer.StackProvider;

import java.util.List;
import java.util.function.Supplier;

/** Makes the class-7 stack the default of every runtime that has this module on its class path. */
public final class SafetyStackProvider implements StackProvider {
    @Override
    public Supplier<List<Layer>> defaultStack() {
        return SafetyStack.defaults();
    }
}
