/** An enum slot's type. */
public enum Size {
    SMALL, MEDIUM, LARGE
}
