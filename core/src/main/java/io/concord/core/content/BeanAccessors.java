package io.concord.core.content;

import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;

/**
 * A JavaBean's properties as JADE's bean ontologies find them: a public getter {@code getX} (or
 * {@code isX} for a boolean) with a public setter {@code setX} of the getter's type; the property
 * is named {@code x}. Used by {@link BeanOntology} and by the JADE compatibility module's.
 */
public final class BeanAccessors {
    private BeanAccessors() {
    }

    /** One property: its name, its getter and its setter. */
    public record Accessor(String name, Method getter, Method setter) {
    }

    /** The class's properties, in the order {@link Class#getMethods()} gives their getters. */
    public static List<Accessor> of(Class<?> c) {
        List<Accessor> out = new ArrayList<>();
        for (Method m : c.getMethods()) {
            String n = m.getName();
            if (m.getParameterCount() != 0 || m.getDeclaringClass() == Object.class || Modifier.isStatic(m.getModifiers())) {
                continue;
            }
            String base;
            if (n.startsWith("get") && n.length() > 3) {
                base = n.substring(3);
            } else if (n.startsWith("is") && n.length() > 2 && (m.getReturnType() == boolean.class || m.getReturnType() == Boolean.class)) {
                base = n.substring(2);
            } else {
                continue;
            }
            try {
                out.add(new Accessor(Character.toLowerCase(base.charAt(0)) + base.substring(1), m, c.getMethod("set" + base, m.getReturnType())));
            } catch (NoSuchMethodException e) {
                // a getter alone is no property
            }
        }
        return out;
    }
}
