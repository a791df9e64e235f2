package jade.content.onto;

/** JADE's default introspector: slots are JavaBean properties ({@code getX}/{@code setX}). */
public class ReflectiveIntrospector implements Introspector {
    private static final long serialVersionUID = 1L;
}
