package jade.content.onto.annotations;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/** The schema name of a bean class, when it is not the class's simple name, as in JADE. */
@Retention(RetentionPolicy.RUNTIME)
@Target(ElementType.TYPE)
public @interface Element {
    /** The default: the class's simple name. */
    String USE_CLASS_SIMPLE_NAME = "__USE_CLASS_SIMPLE_NAME__";

    /** The schema's name. */
    String name() default USE_CLASS_SIMPLE_NAME;
}
